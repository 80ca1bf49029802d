#pragma once
// The first inclusion of Eigen in every translation unit, with one compiler warning silenced.
//
// Every file that includes an Eigen module (or a library that includes Eigen: Ceres, CGAL,
// pybind11/eigen.h) includes this header first. Eigen/Core includes the x86 intrinsics headers
// (immintrin.h) once per translation unit, so the pragmas below cover every later use of them.
//
// Why: GCC 12 with AVX-512 enabled (-march=native on an AVX-512 machine, BPDE_NATIVE=ON) reports
// "'__Y' may be used uninitialized" (-Wmaybe-uninitialized, a few times -Wuninitialized) inside
// avx512fintrin.h wherever Eigen's packet code is inlined, thousands of times in a full build: a
// false positive of the intrinsics header itself (`__m256d __Y = __Y;`, the idiom of
// _mm256_undefined_pd; GCC bug 105593, fixed in later releases). With the same flags it also
// reports -Warray-bounds inside avx512fintrin.h ("array subscript '__m512d_u[0]' is partly outside
// array bounds of 'Eigen::Vector2d'"), a full-width packet load of a fixed 2- or 3-vector on a
// path that Eigen's assignment loop takes only for 8 or more entries. The pragmas cover only the
// Eigen and intrinsics headers, so these warnings stay on for bezierpde's own code. Clang does not
// know -Wmaybe-uninitialized and does not report these, hence the guard.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Warray-bounds"
#include <Eigen/Core>
#pragma GCC diagnostic pop
#else
#include <Eigen/Core>
#endif
