/* Linking: the implementations live in this translation unit only ... */
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
