// The project's own test of the milestone-3 reference against GLM (Debian libglm-dev), an
// independent implementation of the same conventions: OpenGL's right-handed matrices with
// depth in [-1, 1]. Students never need GLM; this only guards the reference.
#define GLM_FORCE_SILENT_WARNINGS
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raster_catch.h"
#include <cmath>
#include <numbers>

#include "transforms.h"

namespace {

namespace ref = m3::reference;

// GLM stores columns: g[col][row]. Ours is m[row][col].
bool same(const ref::Mat4& a, const glm::dmat4& g, double tol = 1e-12) {
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            if (std::abs(a.m[r][c] - g[c][r]) > tol * std::max(1.0, std::abs(g[c][r]))) return false;
        }
    }
    return true;
}

constexpr double kDeg = std::numbers::pi / 180;

}  // namespace

TEST_CASE("m3 reference agrees with GLM: builders", "[glm]") {
    const glm::dmat4 id(1.0);
    CHECK(same(ref::translate({1, -2, 3}), glm::translate(id, glm::dvec3(1, -2, 3))));
    CHECK(same(ref::scale({2, 3, 4}), glm::scale(id, glm::dvec3(2, 3, 4))));
    CHECK(same(ref::rotate_x(0.3), glm::rotate(id, 0.3, glm::dvec3(1, 0, 0))));
    CHECK(same(ref::rotate_y(0.3), glm::rotate(id, 0.3, glm::dvec3(0, 1, 0))));
    CHECK(same(ref::rotate_z(0.3), glm::rotate(id, 0.3, glm::dvec3(0, 0, 1))));
    CHECK(same(ref::rotate({1, -2, 0.5}, 1.3), glm::rotate(id, 1.3, glm::dvec3(1, -2, 0.5))));
    const ref::Mat4 composed = ref::translate({3, 0, 1}) * ref::rotate({0, 1, 1}, 0.7) * ref::scale({2, 2, 1});
    const glm::dmat4 g = glm::scale(glm::rotate(glm::translate(id, glm::dvec3(3, 0, 1)), 0.7, glm::dvec3(0, 1, 1)),
                                    glm::dvec3(2, 2, 1));
    CHECK(same(composed, g));
}

TEST_CASE("m3 reference agrees with GLM: camera and projections", "[glm]") {
    CHECK(same(ref::look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0}),
               glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0))));
    CHECK(same(ref::look_at({-2, 1, 4}, {1, 0.5, -1}, {0.2, 1, 0.1}),
               glm::lookAt(glm::dvec3(-2, 1, 4), glm::dvec3(1, 0.5, -1), glm::dvec3(0.2, 1, 0.1))));
    for (double fov : {1.0, 50.0, 90.0, 179.0}) {
        CHECK(same(ref::perspective(fov, 1.5, 0.1, 100), glm::perspective(fov * kDeg, 1.5, 0.1, 100.0), 1e-11));
    }
    CHECK(same(ref::perspective(60, 1, 1e-4, 1e6), glm::perspective(60 * kDeg, 1.0, 1e-4, 1e6), 1e-11));
    CHECK(same(ref::orthographic(-2, 2, -1, 1, 1, 11), glm::ortho(-2.0, 2.0, -1.0, 1.0, 1.0, 11.0)));
}

TEST_CASE("m3 reference agrees with GLM: inverse", "[glm]") {
    const ref::Mat4 a = ref::translate({3, -1, 2}) * ref::rotate({1, 2, 3}, 0.9) * ref::scale({2, 0.5, 3});
    ref::Mat4 inv;
    REQUIRE(ref::inverse(a, inv));
    glm::dmat4 g(1.0);
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) g[c][r] = a.m[r][c];
    }
    CHECK(same(inv, glm::inverse(g), 1e-10));
    const ref::Mat4 rigid = ref::translate({3, -1, 2}) * ref::rotate({1, 2, 3}, 0.9);
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) g[c][r] = rigid.m[r][c];
    }
    CHECK(same(ref::rigid_inverse(rigid), glm::inverse(g), 1e-10));
}
