// The reference stepper for float, compiled once here instead of in every test
// and tool that steps one (reference/world.h declares it extern).
#include "reference/world.h"

template class manyworlds::reference::World<float>;
