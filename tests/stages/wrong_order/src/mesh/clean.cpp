// A core source that reads files: a library the core may not use, and a relative include.
#include <assimp/scene.h>

#include "../io/off_ply.hpp"
