#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace viewer {

using raster::Vec3;

namespace {
constexpr double kMaxPitch = 89.0 * std::numbers::pi / 180.0;  // never straight up: up stays usable
double clamp_finite(double v, double lo, double hi, double fallback) {
    return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
}
}  // namespace

void OrbitCamera::reset() {
    yaw_ = 0.6;
    pitch_ = 0.35;
    distance_ = 3.6;
    target_ = {};
}

void OrbitCamera::orbit(double yaw, double pitch) {
    if (!std::isfinite(yaw) || !std::isfinite(pitch)) return;
    yaw_ = std::remainder(yaw_ + yaw, 2 * std::numbers::pi);
    pitch_ = std::clamp(pitch_ + pitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dx, double dy) {
    // The screen's right and up directions at the current orbit.
    const Vec3 right{std::cos(yaw_), 0, -std::sin(yaw_)};
    const Vec3 up{-std::sin(pitch_) * std::sin(yaw_), std::cos(pitch_), -std::sin(pitch_) * std::cos(yaw_)};
    const double scale = 2 * distance_ * std::tan(45.0 / 2 * std::numbers::pi / 180);  // view height there
    const Vec3 t = target_ - right * (dx * scale) + up * (dy * scale);
    target_ = {clamp_finite(t.x, -kMaxPan, kMaxPan, target_.x), clamp_finite(t.y, -kMaxPan, kMaxPan, target_.y),
               clamp_finite(t.z, -kMaxPan, kMaxPan, target_.z)};
}

void OrbitCamera::zoom(double factor) {
    distance_ = clamp_finite(distance_ * factor, kMinDistance, kMaxDistance, distance_);
}

Vec3 OrbitCamera::eye() const {
    const Vec3 back{std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_)};
    return target_ + back * distance_;
}

View OrbitCamera::view(double model_yaw, double fovy_degrees, double scene_radius) const {
    View v;
    v.eye = eye();
    v.target = target_;
    v.up = {0, 1, 0};
    v.fovy_degrees = fovy_degrees;
    v.model_yaw = model_yaw;
    // The model lies within distance 1 of the origin (the scene within scene_radius): between
    // d - r and d + r from the eye. Hugging it keeps depth precise far away; inside it, near
    // stays a small positive number.
    const double r = std::isfinite(scene_radius) && scene_radius >= 1 ? scene_radius : 1.0;
    const double d = raster::length(v.eye);
    v.near = std::max(d - r - 0.05, 1e-3);
    v.far = std::max(d + r + 0.05, 2 * v.near);
    return v;
}

std::string OrbitCamera::warning() const {
    const double d = raster::length(eye());
    if (d < 1.0) return "the camera is inside the model's bounding sphere (W, S or the wheel move it; R resets)";
    if (d > 200.0) return "far away: " + std::to_string(static_cast<long long>(d)) + " model radii (R resets)";
    return "";
}

}  // namespace viewer
