// The property tests' random program generator, built into this test binary too.
#include "../model/random_program.cpp"
