// Catch2 2's main(), shared by every test program (Catch2 3 brings its own, Catch2WithMain).
// The checkpoint programs register their test cases at start-up (cp::register_suite).
#define CATCH_CONFIG_MAIN
#include "raster_catch.h"
