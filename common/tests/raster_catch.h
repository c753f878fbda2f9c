// The one place that knows which Catch2 the project is built with. Catch2 2.13 (Debian 12,
// Ubuntu 22.04) is one header, catch2/catch.hpp; Catch2 3 (Debian 13, Ubuntu 24.04, Homebrew,
// vcpkg) is a compiled library with a header per feature and renamed string matchers. Every
// test file includes this header instead of Catch2's own; CMake defines RASTER_CATCH2_MAJOR.
#pragma once

#include <string>

#if RASTER_CATCH2_MAJOR >= 3
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/interfaces/catch_interfaces_capture.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
using Catch::Approx;
namespace raster_test {
inline auto contains(const std::string& text) { return Catch::Matchers::ContainsSubstring(text); }
inline auto starts_with(const std::string& text) { return Catch::Matchers::StartsWith(text); }
}  // namespace raster_test
#else
#include <catch2/catch.hpp>
namespace raster_test {
inline auto contains(const std::string& text) { return Catch::Contains(text); }
inline auto starts_with(const std::string& text) { return Catch::StartsWith(text); }
}  // namespace raster_test
#endif

namespace raster_test {
// The name of the test case running now: test cases registered at run time share one
// function (REGISTER_TEST_CASE takes a plain function) and find their data by this name.
inline std::string current_test_name() { return Catch::getResultCapture().getCurrentTestName(); }
}  // namespace raster_test
