#pragma once
// Shared data builders for the CMC tests.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/tensor_net.h"
#include "tests/random_points.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde::testing {

using bpde::circle_three_arcs;
using bpde::fit_curve;
using bpde::inverse_stereographic;
using bpde::planar_triangle;
using bpde::sphere_square;
using bpde::sphere_triangle;
using bpde::tensor_boundary;
using bpde::triangular_boundary;

}  // namespace bpde::testing
