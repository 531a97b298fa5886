// A public fit header that needs the robot stage, refused.
#pragma once
#include "sphereset/robot.hpp"
