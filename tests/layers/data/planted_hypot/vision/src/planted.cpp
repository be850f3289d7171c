// A planted libm hypot in a controller folder: RingletPortableMath.cmake must name this line.
#include <cmath>
double range(double x, double y) { return std::hypot(x, y); }
