// The deformed wall of one finite-element simulation for viewing: an HDF5 file of the mesh,
// the displacement per vertex and the membrane stresses per face, with an XDMF file that
// describes it so that ParaView (or VisIt) opens it directly.
#pragma once

#include <string>

#include "growthuq/fe/indentation.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {

// Writes `xdmf_path` (must end in ".xdmf") and the HDF5 file beside it, "<stem>.h5". Layout
// (lengths in um, stresses in MPa, 2-D row-major datasets as numpy reads them):
//   /mesh/reference       [n_vertices, 3] float64  unstressed positions, um
//   /mesh/deformed        [n_vertices, 3] float64  final positions, um
//   /mesh/faces           [n_faces, 3]    int64    vertex indices, counter-clockwise from outside
//   /vertex/displacement  [n_vertices, 3] float64  deformed - reference, um
//   /face/sigma1, /face/sigma2, /face/von_mises  [n_faces] float64, MPa
//   /face/thickness_stretch                       [n_faces] float64, h / h0
// Both files go through "<path>.partial" and a rename, so a failure leaves neither half-written;
// with Overwrite::refuse an existing file is an InputError naming it (before anything is written).
// An inconsistent field (sizes, an index out of range, a non-finite value) is an InputError too.
void write_shell_field(const ShellFeField& field, const std::string& xdmf_path, Overwrite overwrite);

// "<stem>.h5" for "<stem>.xdmf" (where write_shell_field puts the data).
std::string shell_field_data_path(const std::string& xdmf_path);

}  // namespace growthuq
