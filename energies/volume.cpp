#include "bezierpde/energies/volume.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/columns3.h"
#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

VolumeForm VolumeForm::triangular(int n) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("VolumeForm: triangular degree " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
  const int q = (3 * n + 1) / 2;  // exact for total degree 2q-2 >= 3n-2
  const QuadratureRuleTriangle rule = gauss_triangle(q);
  VolumeForm f;
  f.w_ = rule.w;
  f.B_ = triangular_basis_table(n, rule.uv, 0, 0);
  f.Bu_ = triangular_basis_table(n, rule.uv, 1, 0);
  f.Bv_ = triangular_basis_table(n, rule.uv, 0, 1);
  f.triangular_ = true;
  f.n_ = f.m_ = n;
  const auto I = triangular_multi_indices(n);
  f.interior_.resize(I.size());
  for (size_t r = 0; r < I.size(); ++r) f.interior_[r] = (I[r][0] > 0 && I[r][1] > 0 && I[r][2] > 0);
  f.Du_ = triangular_derivative_operator(n, 1, 0);
  f.Dv_ = triangular_derivative_operator(n, 0, 1);
  f.Mt_ = triangular_product_integrals(2 * n - 1, n - 1);
  auto mults = [](int d) {
    const auto J = triangular_multi_indices(d);
    Eigen::VectorXd v(static_cast<Eigen::Index>(J.size()));
    for (size_t r = 0; r < J.size(); ++r) v(static_cast<Eigen::Index>(r)) = multinomial(d, J[r][0], J[r][1]);
    return v;
  };
  f.mult_n_ = mults(n);
  f.mult_n1_ = mults(n - 1);
  f.mult_2n1_ = mults(2 * n - 1);
  return f;
}

VolumeForm VolumeForm::tensor(int n, int m) {
  if (n < 1 || n > kMaxDegree || m < 1 || m > kMaxDegree)
    throw DegreeError("VolumeForm: tensor degree (" + std::to_string(n) + ", " + std::to_string(m) +
                      ") is outside 1.." + std::to_string(kMaxDegree));
  // Bidegree (3n-1, 3m-1): Gauss-Legendre with q points is exact to degree 2q-1.
  const QuadratureRule1D gu = gauss_legendre01((3 * n + 1) / 2);
  const QuadratureRule1D gv = gauss_legendre01((3 * m + 1) / 2);
  const Eigen::MatrixXd Tu[2] = {bernstein_table(n, gu.x, 0), bernstein_table(n, gu.x, 1)};
  const Eigen::MatrixXd Tv[2] = {bernstein_table(m, gv.x, 0), bernstein_table(m, gv.x, 1)};
  const Eigen::Index qu = gu.x.size(), qv = gv.x.size(), N = (n + 1) * (m + 1);
  VolumeForm f;
  f.w_.resize(qu * qv);
  f.B_.resize(qu * qv, N);
  f.Bu_.resize(qu * qv, N);
  f.Bv_.resize(qu * qv, N);
  for (Eigen::Index a = 0; a < qu; ++a)
    for (Eigen::Index b = 0; b < qv; ++b) {
      const Eigen::Index s = a * qv + b;
      f.w_(s) = gu.w(a) * gv.w(b);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j) {
          const Eigen::Index c = i * (m + 1) + j;
          f.B_(s, c) = Tu[0](a, i) * Tv[0](b, j);
          f.Bu_(s, c) = Tu[1](a, i) * Tv[0](b, j);
          f.Bv_(s, c) = Tu[0](a, i) * Tv[1](b, j);
        }
    }
  f.triangular_ = false;
  f.n_ = n;
  f.m_ = m;
  f.interior_.resize(static_cast<size_t>(N));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) f.interior_[static_cast<size_t>(i * (m + 1) + j)] = (i > 0 && i < n && j > 0 && j < m);
  f.Mu1_ = bernstein_product_integrals(2 * n, n - 1);
  f.Mv1_ = bernstein_product_integrals(2 * m - 1, m);
  f.Mu2_ = bernstein_product_integrals(2 * n - 1, n);
  f.Mv2_ = bernstein_product_integrals(2 * m, m - 1);
  return f;
}

std::size_t VolumeForm::memory_bytes() const {
  return sizeof(double) *
             static_cast<std::size_t>(w_.size() + B_.size() + Bu_.size() + Bv_.size() + Du_.size() + Dv_.size() +
                                      Mt_.size() + mult_n_.size() + mult_n1_.size() + mult_2n1_.size() + Mu1_.size() +
                                      Mv1_.size() + Mu2_.size() + Mv2_.size()) +
         interior_.size();
}

void VolumeForm::check(const Eigen::MatrixX3d& P) const {
  if (P.rows() != B_.cols())
    throw SizeError("VolumeForm: " + std::to_string(P.rows()) + " points given, the net has " +
                    std::to_string(B_.cols()));
}

double VolumeForm::value(const Eigen::MatrixX3d& P) const {
  if (assembly_) return assembled_value(P, false);
  check(P);
  const Eigen::MatrixX3d X = times(B_, P), Xu = times(Bu_, P), Xv = times(Bv_, P);
  const Eigen::MatrixX3d N = cross_rows(Xu, Xv);
  return w_.dot(N.cwiseProduct(X).rowwise().sum()) / 3.0;
}

double VolumeForm::value_scale(const Eigen::MatrixX3d& P) const {
  if (assembly_) return assembled_value(P, true);
  check(P);
  const Eigen::MatrixX3d X = times(B_, P), Xu = times(Bu_, P), Xv = times(Bv_, P);
  const Eigen::MatrixX3d N = cross_rows(Xu, Xv);
  return w_.dot(N.cwiseProduct(X).rowwise().sum().cwiseAbs()) / 3.0;
}

Eigen::MatrixX3d VolumeForm::gradient(const Eigen::MatrixX3d& P) const {
  if (assembly_) return assembled_gradient(P, false);
  check(P);
  const Eigen::MatrixX3d X = times(B_, P), Xu = times(Bu_, P), Xv = times(Bv_, P);
  const Eigen::MatrixX3d a = w_.asDiagonal() * cross_rows(Xv, X);
  const Eigen::MatrixX3d b = w_.asDiagonal() * cross_rows(X, Xu);
  const Eigen::MatrixX3d c = w_.asDiagonal() * cross_rows(Xu, Xv);
  return (times_t(Bu_, a) + times_t(Bv_, b) + times_t(B_, c)) / 3.0;
}

Eigen::MatrixX3d VolumeForm::gradient_scale(const Eigen::MatrixX3d& P) const {
  if (assembly_) return assembled_gradient(P, true);
  check(P);
  const Eigen::MatrixX3d X = times(B_, P), Xu = times(Bu_, P), Xv = times(Bv_, P);
  const Eigen::MatrixX3d a = w_.asDiagonal() * cross_rows(Xv, X).cwiseAbs();
  const Eigen::MatrixX3d b = w_.asDiagonal() * cross_rows(X, Xu).cwiseAbs();
  const Eigen::MatrixX3d c = w_.asDiagonal() * cross_rows(Xu, Xv).cwiseAbs();
  return (Bu_.cwiseAbs().transpose() * a + Bv_.cwiseAbs().transpose() * b + B_.cwiseAbs().transpose() * c) / 3.0;
}

bool VolumeForm::all_interior(const std::vector<int>& idx) const {
  for (int I : idx) {
    if (I < 0 || I >= B_.cols()) throw SizeError("VolumeForm: point index out of range");
    if (!interior_[static_cast<size_t>(I)]) return false;
  }
  return true;
}

Eigen::MatrixXd VolumeForm::hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  if (assembly_) return assembled_hessian(P, idx, false);
  check(P);
  if (all_interior(idx)) return triangular_ ? hessian_interior_triangular(P, idx) : hessian_interior_tensor(P, idx);
  return hessian_quadrature(P, idx);
}

namespace {

// Writes the 3x3 block [a]_x of the pair (I, L) into Hs.
inline void put_cross(Eigen::MatrixXd& Hs, Eigen::Index I, Eigen::Index L, const Eigen::Vector3d& a) {
  Hs(3 * I + 0, 3 * L + 1) = -a(2);
  Hs(3 * I + 0, 3 * L + 2) = a(1);
  Hs(3 * I + 1, 3 * L + 0) = a(2);
  Hs(3 * I + 1, 3 * L + 2) = -a(0);
  Hs(3 * I + 2, 3 * L + 0) = -a(1);
  Hs(3 * I + 2, 3 * L + 1) = a(0);
}

}  // namespace

Eigen::MatrixXd VolumeForm::hessian_interior_triangular(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  // a_IL = ∫ B_I (B_L)_v x_u - ∫ B_I (B_L)_u x_v, with
  //   B_I^n (B_L^n)_v = n [beta(I, L-e2) B^{2n-1}_{I+L-e2} - beta(I, L-e3) B^{2n-1}_{I+L-e3}],
  //   beta(I, J) = mult(n, I) mult(n-1, J) / mult(2n-1, I+J)   (B_I^n B_J^{n-1} = beta B_{I+J}^{2n-1}),
  //   ∫ B^{2n-1}_S x_u = Wu(S) = (Mt * (Du P))(S), and likewise for (B_L)_u and x_v.
  const int n = n_;
  const Eigen::MatrixX3d Wu = times(Mt_, times(Du_, P));
  const Eigen::MatrixX3d Wv = times(Mt_, times(Dv_, P));
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  std::vector<std::array<int, 3>> J(static_cast<size_t>(k));
  {
    const auto all = triangular_multi_indices(n);
    for (Eigen::Index a = 0; a < k; ++a)
      J[static_cast<size_t>(a)] = all[static_cast<size_t>(idx[static_cast<size_t>(a)])];
  }
  // Contribution n * beta(I, L - e_r) * W(I + L - e_r) (zero if L_r = 0).
  auto term = [&](const std::array<int, 3>& I, const std::array<int, 3>& L, int r,
                  const Eigen::MatrixX3d& W) -> Eigen::Vector3d {
    if (L[static_cast<size_t>(r)] == 0) return Eigen::Vector3d::Zero();
    std::array<int, 3> Lr = L;
    --Lr[static_cast<size_t>(r)];
    const double beta = mult_n_(TriangularNet::index(n, I[0], I[1])) *
                        mult_n1_(TriangularNet::index(n - 1, Lr[0], Lr[1])) /
                        mult_2n1_(TriangularNet::index(2 * n - 1, I[0] + Lr[0], I[1] + Lr[1]));
    return n * beta * W.row(TriangularNet::index(2 * n - 1, I[0] + Lr[0], I[1] + Lr[1])).transpose();
  };
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = a + 1; b < k; ++b) {
      const auto& I = J[static_cast<size_t>(a)];
      const auto& L = J[static_cast<size_t>(b)];
      const Eigen::Vector3d v = term(I, L, 1, Wu) - term(I, L, 2, Wu) - term(I, L, 0, Wv) + term(I, L, 2, Wv);
      put_cross(Hs, a, b, v);
      put_cross(Hs, b, a, -v);
    }
  return Hs;
}

Eigen::MatrixXd VolumeForm::hessian_interior_tensor(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  // I = (i,j), L = (k,l).  a_IL = ∫ B_I (B_L)_v x_u - ∫ B_I (B_L)_u x_v with
  //   B_I (B_L)_v = g_n(i,k) B^{2n}_{i+k}(u) * m [h_m(j,l-1) B^{2m-1}_{j+l-1}(v) - h_m(j,l) B^{2m-1}_{j+l}(v)],
  //   g_n(i,k) = C(n,i)C(n,k)/C(2n,i+k),  h_m(j,l) = C(m,j)C(m-1,l)/C(2m-1,j+l),
  //   ∫ B^{2n}_a(u) B^{2m-1}_b(v) x_u = Wu(a,b) = (Mu1 Xu Mv1^T)(a,b), Xu = n (P_{i+1,j} - P_{ij}).
  const int n = n_, m = m_;
  std::array<Eigen::MatrixXd, 3> Wu, Wv;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd Xu(n, m + 1), Xv(n + 1, m);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) {
        if (i < n) Xu(i, j) = n * (P((i + 1) * (m + 1) + j, c) - P(i * (m + 1) + j, c));
        if (j < m) Xv(i, j) = m * (P(i * (m + 1) + j + 1, c) - P(i * (m + 1) + j, c));
      }
    Wu[static_cast<size_t>(c)] = Mu1_ * Xu * Mv1_.transpose();  // (2n+1) x 2m
    Wv[static_cast<size_t>(c)] = Mu2_ * Xv * Mv2_.transpose();  // 2n x (2m+1)
  }
  auto g = [](int d, int i, int k) { return binomial(d, i) * binomial(d, k) / binomial(2 * d, i + k); };
  auto h = [](int d, int j, int l) {
    if (l < 0 || l > d - 1) return 0.0;
    return binomial(d, j) * binomial(d - 1, l) / binomial(2 * d - 1, j + l);
  };
  const Eigen::Index K = static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * K, 3 * K);
  for (Eigen::Index a = 0; a < K; ++a)
    for (Eigen::Index b = a + 1; b < K; ++b) {
      const int IA = idx[static_cast<size_t>(a)], LB = idx[static_cast<size_t>(b)];
      const int i = IA / (m + 1), j = IA % (m + 1), k = LB / (m + 1), l = LB % (m + 1);
      Eigen::Vector3d v;
      const double gu = g(n, i, k), gv = g(m, j, l);
      const double h1 = h(m, j, l - 1), h2 = h(m, j, l), h3 = h(n, i, k - 1), h4 = h(n, i, k);
      for (int c = 0; c < 3; ++c) {
        const Eigen::MatrixXd& U = Wu[static_cast<size_t>(c)];
        const Eigen::MatrixXd& W = Wv[static_cast<size_t>(c)];
        double t1 = 0, t2 = 0;
        if (h1 != 0) t1 += h1 * U(i + k, j + l - 1);
        if (h2 != 0) t1 -= h2 * U(i + k, j + l);
        if (h3 != 0) t2 += h3 * W(i + k - 1, j + l);
        if (h4 != 0) t2 -= h4 * W(i + k, j + l);
        v(c) = gu * m * t1 - gv * n * t2;
      }
      put_cross(Hs, a, b, v);
      put_cross(Hs, b, a, -v);
    }
  return Hs;
}

void VolumeForm::gradient_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                         Eigen::MatrixX3d* S) const {
  if (assembly_) {
    assembled_rows_and_scale(P, idx, G, S);
    return;
  }
  check(P);
  if (all_interior(idx)) {
    const Eigen::MatrixX3d N = cross_rows(times(Bu_, P), times(Bv_, P));
    const Eigen::MatrixXd Bs = B_(Eigen::all, idx);
    if (G) *G = times_t(Bs, w_.asDiagonal() * N);  // Bernstein values are >= 0 on the domain
    if (S) *S = times_t(Bs, w_.asDiagonal() * N.cwiseAbs());
    return;
  }
  if (G) {
    const Eigen::MatrixX3d F = gradient(P);
    *G = F(idx, Eigen::all);
  }
  if (S) {
    const Eigen::MatrixX3d F = gradient_scale(P);
    *S = F(idx, Eigen::all);
  }
}

Eigen::MatrixX3d VolumeForm::gradient_rows(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  Eigen::MatrixX3d G;
  gradient_rows_and_scale(P, idx, &G, nullptr);
  return G;
}

Eigen::MatrixX3d VolumeForm::gradient_scale_rows(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  Eigen::MatrixX3d S;
  gradient_rows_and_scale(P, idx, nullptr, &S);
  return S;
}

Eigen::MatrixXd VolumeForm::hessian_quadrature(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  if (assembly_) return assembled_hessian(P, idx, true);
  check(P);
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  const Eigen::Index q = w_.size();
  Eigen::MatrixXd Bs(q, k), Bus(q, k), Bvs(q, k);
  for (Eigen::Index a = 0; a < k; ++a) {
    const int c = idx[static_cast<size_t>(a)];
    if (c < 0 || c >= B_.cols()) throw SizeError("VolumeForm::hessian: index out of range");
    Bs.col(a) = B_.col(c);
    Bus.col(a) = Bu_.col(c);
    Bvs.col(a) = Bv_.col(c);
  }
  const Eigen::MatrixX3d X = times(B_, P), Xu = times(Bu_, P), Xv = times(Bv_, P);
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  Eigen::MatrixXd tmp(q, k);
  for (int c = 0; c < 3; ++c) {
    // M_c(I,L) = ∫ (B_I)_v x_c (B_L)_u + (B_I)_u (x_v)_c B_L + B_I (x_u)_c (B_L)_v;  A = (M - M^T)/3.
    tmp = (w_.cwiseProduct(X.col(c))).asDiagonal() * Bus;
    Eigen::MatrixXd M = Bvs.transpose() * tmp;
    tmp = (w_.cwiseProduct(Xv.col(c))).asDiagonal() * Bs;
    M.noalias() += Bus.transpose() * tmp;
    tmp = (w_.cwiseProduct(Xu.col(c))).asDiagonal() * Bvs;
    M.noalias() += Bs.transpose() * tmp;
    const Eigen::MatrixXd A = (M - M.transpose()) / 3.0;
    // [a]_x = [[0,-a3,a2],[a3,0,-a1],[-a2,a1,0]]: component c sits at (r, s) with r, s != c.
    const int r = (c + 2) % 3, s = (c + 1) % 3;  // [a]_x(r,s) = +a_c when (r,s) = (c+2, c+1)
    for (Eigen::Index I = 0; I < k; ++I)
      for (Eigen::Index L = 0; L < k; ++L) {
        Hs(3 * I + r, 3 * L + s) += A(I, L);
        Hs(3 * I + s, 3 * L + r) -= A(I, L);
      }
  }
  return Hs;
}

double volume(const TriangularNet& net) { return VolumeForm::triangular(net.n()).value(net.points()); }

double volume(const TensorNet& net) { return VolumeForm::tensor(net.n(), net.m()).value(net.points()); }

double volume_coefficient(int n, const std::array<int, 3>& I, const std::array<int, 3>& J,
                          const std::array<int, 3>& K) {
  int S[3];
  for (int r = 0; r < 3; ++r) S[r] = I[r] + J[r] + K[r];
  auto d = [&](int r, int s) {
    const double num = static_cast<double>(I[r]) * J[s] - static_cast<double>(J[r]) * I[s];
    if (num == 0.0) return 0.0;
    return num / (static_cast<double>(S[r]) * S[s]);
  };
  const double ratio = multinomial(n, I[0], I[1]) * multinomial(n, J[0], J[1]) * multinomial(n, K[0], K[1]) /
                       multinomial(3 * n, S[0], S[1]);
  return ratio * (d(0, 1) + d(1, 2) - d(0, 2));
}

double volume_closed_form(int n, const Eigen::MatrixX3d& P) {
  const auto I = triangular_multi_indices(n);
  const Eigen::Index N = static_cast<Eigen::Index>(I.size());
  if (P.rows() != N) throw SizeError("volume_closed_form: wrong number of points");
  double V = 0;
  for (Eigen::Index a = 0; a < N; ++a)
    for (Eigen::Index b = 0; b < N; ++b) {
      if (a == b) continue;  // C_IIK = 0
      const Eigen::Vector3d cr = P.row(a).transpose().cross(P.row(b).transpose());
      for (Eigen::Index c = 0; c < N; ++c) {
        const double C =
            volume_coefficient(n, I[static_cast<size_t>(a)], I[static_cast<size_t>(b)], I[static_cast<size_t>(c)]);
        V += C * cr.dot(P.row(c).transpose());
      }
    }
  return V / 6.0;
}

}  // namespace bpde
