// A fit source that reads files: a later stage, refused.
#include "io/off_ply.hpp"
