// Attack: read a file of the grading machine at compile time, to see it quoted in the compile
// log that the student is shown (the first lines of /etc/passwd are not C++).
#include "/etc/passwd"
