// Students can ignore this file.
//
// Every milestone header wraps its functions in `inline namespace RASTER_FLAVOUR`. For the
// student's code the build leaves it at `student`, and calls such as m1::draw_line(...) work
// as if the extra namespace were not there. The reference solution is compiled a second time
// with RASTER_FLAVOUR=reference, so both can be linked into one checkpoint program: it then
// times the student's code and the reference on the same scene, in the same process.
#pragma once

#ifndef RASTER_FLAVOUR
#define RASTER_FLAVOUR student
#endif
