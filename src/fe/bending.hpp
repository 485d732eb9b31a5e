// The bending element of the Kirchhoff-Love shell: rotation-free, on the stencil of a face and its
// three edge neighbours (18 dofs). Koiter's bending energy with the change of the second
// fundamental form of a quadratic patch interpolant; analytic gradient and Hessian.
//
// Formulation (after the Basic Shell Triangle of Onate and Zarate 2000, IJNME 47:557, and its
// large-strain form with a quadratic patch interpolation, Flores and Onate 2001, IJNME 51:57):
// the six stencil vertices are interpolated by the quadratic map phi(xi) over orthonormal
// coordinates xi of the face's reference plane (6 points, 6 quadratic monomials); its second
// derivatives phi_ab are constant and linear in the positions. The face's second fundamental form
// is II_ab = phi_ab . n with n the unit normal of the deformed face, and the energy per unit
// reference area is Koiter's
//   W = B/2 [ (1 - nu) tr(M^2) + nu (tr M)^2 ],  M = a0^-1 (II - II0),  B = E t^3 / (12 (1 - nu^2)),
// a0 = I the reference metric in xi (II0 the same construction on the reference positions).
// The quadratic interpolant reproduces every quadratic surface exactly, so M is consistent on
// any mesh, irregular or graded (test_bending.cpp measures it on jittered meshes: inflating a
// curved cylinder or sphere reference and bending a flat patch into a cylinder converge at
// second order in the mean error per face; the non-isometric bending of a flat patch onto a sphere at first order
// per face and second order in the patch's total energy). Dihedral-angle energies (Grinspun et
// al. 2003) and mid-edge normals averaged from the two faces, by contrast, depend on the mesh's
// regularity. The energy is invariant under rigid motions and zero for any in-plane deformation
// of a flat patch.
//
// Edge kinds. interior: the neighbour's vertex wi. mirror: the edge lies on the symmetry plane
// y = 0, the neighbour is this face's mirror image, so wi is replaced by the reflection of vi
// (y -> -y); wi's slot gets zero derivative. free (an open edge): no neighbour; the curvature
// component that the missing vertex would fix (the direction q = d II / d (w . n) of the
// interpolant) is left free and the energy minimised over it (a static condensation of the
// quadratic form: D <- D - D q q^T D / (q^T D q)), so the edge transmits no moment conjugate to
// it; wi's slot gets zero derivative. q depends on the stencil's shape and is the edge's normal
// curvature direction n_e n_e^T only for symmetric stencils, so this is the moment-free edge in an
// element-wise sense; it acts on the boundary row of faces only (for the tube, the pinned distal
// end, far from the probe).
#pragma once

#include <Eigen/Core>
#include <array>

#include "fe/material_law.hpp"

namespace growthuq::fe {

enum class EdgeKind { interior, mirror, free };

// Vertices v0, v1, v2 of the face (counter-clockwise seen from outside), then w0, w1, w2, where wi
// is the vertex across the edge opposite vi (unused, any index, for mirror and free edges).
struct BendingStencil {
  std::array<int, 6> vertices;
  std::array<EdgeKind, 3> edges;
};

// Reference data of one stencil. Components of symmetric 2x2 forms are ordered (11, 22, 12).
struct BendingReference {
  Eigen::Matrix<double, 3, 6> fit;       // phi_ab = sum_k fit(ab, k) p_k over the six stencil points
  Eigen::Vector3d reference_form;        // II0
  std::array<Eigen::Vector3d, 3> free_directions;  // q of each free edge
  int free_count = 0;
  double area = 0.0;                     // reference area of the face
};

// X = the 6 stencil positions stacked (reference). Throws InputError if the face is degenerate or
// the six points admit no unique quadratic interpolant (all on one conic).
BendingReference make_bending_reference(const BendingStencil& stencil, const Eigen::Matrix<double, 18, 1>& X);

// Bending energy area * W of the face; gradient and Hessian optional (nullptr = not wanted),
// exact. Uses material.young and material.poisson; t = bending_thickness (h0/d0 in the solver).
double bending_energy(const WallMaterial& material, double bending_thickness, const BendingStencil& stencil,
                      const BendingReference& reference, const Eigen::Matrix<double, 18, 1>& x,
                      Eigen::Matrix<double, 18, 1>* gradient, Eigen::Matrix<double, 18, 18>* hessian);

// The change of the second fundamental form M = II - II0 (11, 22, 12) of a state, for output and
// tests (curvature change in the reference basis).
Eigen::Vector3d bending_curvature_change(const BendingStencil& stencil, const BendingReference& reference,
                                         const Eigen::Matrix<double, 18, 1>& x);

}  // namespace growthuq::fe
