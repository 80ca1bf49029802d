#pragma once
// C = A * B for small dense row-major matrices: the inner kernel of tensor-patch evaluation on a
// grid (TensorNet::evaluate_grid), where it carries the Table 1 benchmark (Arnal–Monterde–Ugail §7: a 50 x 50
// evaluation after every solve).
//
//   A: r by k, row-major, leading dimension lda (>= k)
//   B: k by w, row-major, leading dimension ldb (>= w)
//   C: r by w, row-major, leading dimension ldc (>= w); overwritten
//
// Method. Rows of C are accumulated in registers over k (C(a, :) = sum_i A(a, i) B(i, :)), two
// rows and 24 columns at a time (an odd row count starts with three rows and 16 columns, a single
// row takes 32 columns), then 4 columns, then the last 1-3 columns with masked loads. On x86-64 CPUs with AVX2
// and FMA (checked once at run time, so the library stays portable to any x86-64) the accumulation uses 256-bit fused
// multiply-adds; elsewhere the same loop runs in portable C++. Both paths sum in the same order
// (i = 0..k-1 for every entry), so results differ only by the rounding of fused versus separate
// multiply-add.
//
// Why not Eigen's product: measured by the Kernel/* routes of bpde_bench against Eigen's product on
// the same operands at the same flags (docs/performance_measurements.md, "Kernels"). In the portable
// build (BPDE_NATIVE=OFF: Eigen sees SSE2 only) this kernel wins on every shape; in the native build
// it wins on the mould product and on the small grids, and the large grids are level with Eigen.
//
// Example: evaluate a degree-(n, m) patch coordinate P (row-major (n+1) x (m+1)) on a grid,
//   T = P * BvT        (BvT: (m+1) x #v, row j = B_j^m at the v's)
//   X = Bu * T         (Bu: #u x (n+1), row a = B_i^n(u_a))
// which is 2 (n+1) #u #v + 2 (n+1)(m+1) #v flops.
namespace bpde {

/// SizeError for negative sizes or a leading dimension smaller than its row (pointers are trusted:
/// A holds r rows of lda, B k rows of ldb, C r rows of ldc).
void row_major_product(const double* A, int r, int k, int lda, const double* B, int w, int ldb, double* C, int ldc);

/// True when row_major_product runs its AVX2/FMA path on this CPU.
bool row_major_product_uses_fma();

}  // namespace bpde
