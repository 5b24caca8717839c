// The filament network's part of checkpoint.h5 (group /filaments): filaments with their
// beads and monomer lattices, bound linkers and motors, and branches. Tensions, loads and
// candidate binding pairs are not stored: they follow from the positions.
#pragma once

#include "io/hdf5_file.hpp"
#include "sim/system_state.hpp"

namespace cortex {

void writeFilamentState(h5::File& file, const FilamentState& state);
// Throws InputError naming the file for malformed data.
FilamentState readFilamentState(const h5::File& file, const std::string& file_name);

}  // namespace cortex
