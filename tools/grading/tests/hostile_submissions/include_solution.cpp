// Attack: compile the model answer in, by its absolute path (paths are no secret: `ps` shows
// them) and by the relative path a student's own checkout has. Neither is visible in the
// grader's sandbox: this must not compile.
#if __has_include("@SOURCE@/solutions/milestone1_lines/lines.cpp")
#include "@SOURCE@/solutions/milestone1_lines/lines.cpp"
#elif __has_include("../solutions/milestone1_lines/lines.cpp")
#include "../solutions/milestone1_lines/lines.cpp"
#else
#error the solution is not visible from here
#endif
