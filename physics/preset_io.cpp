#include "preset_io.hpp"
