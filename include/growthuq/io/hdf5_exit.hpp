// What the command-line program needs to know of HDF5 at exit, without HDF5's headers (the CLI
// is built without them).
#pragma once

namespace growthuq::hdf5 {

// Whether a file could not be closed (a flush that failed half way leaves HDF5 holding it half
// closed). HDF5's own clean-up at exit would then crash on it (SIGSEGV after the message): the
// command-line program ends without that clean-up instead (cli/main.cpp).
bool file_left_half_closed();
// Records that one was (results_h5.cpp, when a close fails).
void note_file_left_half_closed();

}  // namespace growthuq::hdf5
