#pragma once
// The scalar types of bezierpde and their Eigen aliases, named once.
//
//   double       every public interface, nets, energies, results;
//   long double  x87 extended precision (64-bit mantissa): the factorisations of the
//                ill-conditioned Bernstein systems (solvers/pde, solvers/c1, the extremal basis);
//   quad         IEEE binary128 (GCC's __float128, 113-bit mantissa): residuals and exact
//                operator entries beyond long double (solvers/c1). Eigen has no NumTraits for it,
//                so binary128 data lives in std::vector (row-major where it is a matrix).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

namespace bpde {

using quad = __float128;

using MatLD = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
using VecLD = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

}  // namespace bpde
