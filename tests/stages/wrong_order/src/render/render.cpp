// The picture needs nothing of the robot: a stage beside it, not before it.
#include <sphereset/robot.hpp>
