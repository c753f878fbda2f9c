// Builders the milestones' scene tables share. Each milestone has Scene and Camera types of its
// own; these fill in the fields of the same names and leave the rest at their defaults.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "raster/vec.h"

namespace cp {

// A checkpoint of numbers alone: 16 x 16, no panels, the given number groups.
template <typename Scene>
Scene numbers_scene(std::string id, std::string title, std::string hint, std::vector<int> todos,
                    decltype(Scene::groups) groups) {
    Scene s;
    s.id = std::move(id);
    s.title = std::move(title);
    s.hint = std::move(hint);
    s.todos = std::move(todos);
    s.width = s.height = 16;
    s.groups = std::move(groups);
    return s;
}

// A picture checkpoint of w x h pixels; the caller adds its panels.
template <typename Scene>
Scene picture_scene(std::string id, std::string title, std::string hint, std::vector<int> todos, int w, int h) {
    Scene s;
    s.id = std::move(id);
    s.title = std::move(title);
    s.hint = std::move(hint);
    s.todos = std::move(todos);
    s.width = w;
    s.height = h;
    return s;
}

// A camera looking from eye at target, with its near and far planes.
template <typename Camera>
Camera camera_at(raster::Vec3 eye, raster::Vec3 target, double near, double far) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.near = near;
    c.far = far;
    return c;
}

}  // namespace cp
