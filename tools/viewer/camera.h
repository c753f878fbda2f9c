// An orbit camera around a model that fits in the unit sphere at the origin (model.h scales
// every model so). Plain math, no milestone code: the flavours turn its View into matrices.
//
// Every state is safe to draw: the distance, the pitch and the pan are clamped to finite
// ranges, and near and far are chosen around the model from wherever the camera is (inside
// it, behind it, a million radii away), so that 0 < near < far always holds.
#pragma once

#include <string>

#include "flavour_api.h"

namespace viewer {

class OrbitCamera {
public:
    static constexpr double kMinDistance = 1e-3;  // model radii
    static constexpr double kMaxDistance = 1e6;
    static constexpr double kMaxPan = 1e4;

    OrbitCamera() { reset(); }
    void reset();

    // Turns around the target: yaw about the world's y axis, pitch up and down (radians).
    void orbit(double yaw, double pitch);
    // Moves the target (and the camera with it) across the screen: dx, dy in fractions of the
    // view's height at the target's distance (so a drag moves the model with the mouse).
    void pan(double dx, double dy);
    // Multiplies the distance to the target by factor (< 1: closer).
    void zoom(double factor);

    // The view for a scene within `scene_radius` of the origin (near and far hug that sphere).
    View view(double model_yaw, double fovy_degrees = 45, double scene_radius = 1) const;
    raster::Vec3 eye() const;
    double distance() const { return distance_; }

    // A warning for the screen about where the camera is, or "" (inside the model, far away).
    std::string warning() const;

private:
    double yaw_ = 0, pitch_ = 0, distance_ = 3;
    raster::Vec3 target_;
};

}  // namespace viewer
