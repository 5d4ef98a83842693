#include "visors/optim/cone.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace visors::optim {
namespace {

double dot(const double* a, const double* b, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

// u'Ju = u0^2 - ||u1||^2.
double jdot(const double* a, const double* b, int n) { return a[0] * b[0] - dot(a + 1, b + 1, n - 1); }

// Largest a <= cap with (x + a d) in Q^q for x in its interior: f(a) = (x+ad)'J(x+ad) =
// A a^2 + 2 B a + C with C > 0; the first positive root of f bounds the step (the segment cannot
// leave Q through the apex without f vanishing, and stays in Q rather than -Q by continuity).
double soc_step(const double* x, const double* d, int q, double cap) {
  if (q == 1) return d[0] < 0.0 ? std::min(cap, -x[0] / d[0]) : cap;
  const double a = jdot(d, d, q);
  const double b = jdot(x, d, q);
  const double c = jdot(x, x, q);
  double root = std::numeric_limits<double>::infinity();
  if (std::abs(a) <= 1e-300) {
    if (b < 0.0) root = -c / (2.0 * b);
  } else {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      // Stable roots: r1 = (-b - sign(b) sqrt(disc)) / a, r2 = c / (a r1).
      const double sq = std::sqrt(disc);
      const double t = b >= 0.0 ? -b - sq : -b + sq;
      const double r1 = t / a;
      const double r2 = t != 0.0 ? c / t : std::numeric_limits<double>::infinity();
      if (r1 > 0.0) root = std::min(root, r1);
      if (r2 > 0.0) root = std::min(root, r2);
    }
  }
  // The cone's half of the double cone also requires x0 + a d0 >= 0.
  if (d[0] < 0.0) root = std::min(root, -x[0] / d[0]);
  return std::min(cap, root);
}

}  // namespace

ConeProduct::ConeProduct(int l, std::vector<int> q) : l_(l), q_(std::move(q)) {
  rows_ = l_;
  start_.reserve(q_.size());
  for (const int dim : q_) {
    start_.push_back(rows_);
    rows_ += dim;
  }
}

void ConeProduct::product(const double* u, const double* v, double* out) const {
  for (int i = 0; i < l_; ++i) out[i] = u[i] * v[i];
  for (int k = 0; k < soc_count(); ++k) {
    const int o = start_[k];
    const int q = q_[k];
    const double u0 = u[o];
    const double v0 = v[o];
    const double head = dot(u + o, v + o, q);
    for (int i = 1; i < q; ++i) out[o + i] = u0 * v[o + i] + v0 * u[o + i];
    out[o] = head;
  }
}

void ConeProduct::divide(const double* u, const double* r, double* out) const {
  for (int i = 0; i < l_; ++i) out[i] = r[i] / u[i];
  for (int k = 0; k < soc_count(); ++k) {
    const int o = start_[k];
    const int q = q_[k];
    // u o x = r  =>  x0 = (u0 r0 - u1'r1) / (u'Ju),  x1 = (r1 - x0 u1) / u0.
    const double det = jdot(u + o, u + o, q);
    const double x0 = (u[o] * r[o] - dot(u + o + 1, r + o + 1, q - 1)) / det;
    for (int i = 1; i < q; ++i) out[o + i] = (r[o + i] - x0 * u[o + i]) / u[o];
    out[o] = x0;
  }
}

void ConeProduct::add_identity(double* x, double a) const {
  for (int i = 0; i < l_; ++i) x[i] += a;
  for (int k = 0; k < soc_count(); ++k) x[start_[k]] += a;
}

double ConeProduct::interior_margin(const double* x) const {
  double margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < l_; ++i) margin = std::min(margin, x[i]);
  for (int k = 0; k < soc_count(); ++k) {
    const int o = start_[k];
    margin = std::min(margin, x[o] - std::sqrt(dot(x + o + 1, x + o + 1, q_[k] - 1)));
  }
  return margin;
}

double ConeProduct::max_step(const double* x, const double* d, double cap) const {
  double a = cap;
  for (int i = 0; i < l_; ++i) {
    if (d[i] < 0.0) a = std::min(a, -x[i] / d[i]);
  }
  for (int k = 0; k < soc_count(); ++k) a = soc_step(x + start_[k], d + start_[k], q_[k], a);
  return a;
}

NtScaling::NtScaling(const ConeProduct& cone)
    : cone_(cone),
      w_(static_cast<std::size_t>(cone.rows()), 1.0),
      eta_(static_cast<std::size_t>(cone.soc_count()), 1.0),
      w_inv_(static_cast<std::size_t>(cone.orthant()), 1.0),
      eta_inv_(eta_.size(), 1.0),
      w0_inv_(eta_.size(), 0.5) {
  set_identity();
}

void NtScaling::set_identity() {
  for (int i = 0; i < cone_.orthant(); ++i) {
    w_[i] = 1.0;
    w_inv_[i] = 1.0;
  }
  for (int k = 0; k < cone_.soc_count(); ++k) {
    const int o = cone_.soc_start(k);
    w_[o] = 1.0;
    for (int i = 1; i < cone_.soc_dim(k); ++i) w_[o + i] = 0.0;
    eta_[k] = 1.0;
    eta_inv_[k] = 1.0;
    w0_inv_[k] = 0.5;
  }
}

bool NtScaling::update(const double* s, const double* z, double* lambda) {
  for (int i = 0; i < cone_.orthant(); ++i) {
    if (!(s[i] > 0.0) || !(z[i] > 0.0)) return false;
    w_[i] = std::sqrt(s[i] / z[i]);
    w_inv_[i] = 1.0 / w_[i];
    lambda[i] = std::sqrt(s[i] * z[i]);
  }
  for (int k = 0; k < cone_.soc_count(); ++k) {
    const int o = cone_.soc_start(k);
    const int q = cone_.soc_dim(k);
    const double* sk = s + o;
    const double* zk = z + o;
    const double sjs = jdot(sk, sk, q);
    const double zjz = jdot(zk, zk, q);
    if (!(sk[0] > 0.0) || !(zk[0] > 0.0) || !(sjs > 0.0) || !(zjz > 0.0)) return false;
    const double sn = std::sqrt(sjs);
    const double zn = std::sqrt(zjz);
    eta_[k] = std::sqrt(sn / zn);
    // sb'zb with sb = s/sn, zb = z/zn.
    const double sz = dot(sk, zk, q) / (sn * zn);
    const double gamma = std::sqrt(0.5 * (1.0 + sz));
    double* w = w_.data() + o;
    w[0] = (sk[0] / sn + zk[0] / zn) / (2.0 * gamma);
    for (int i = 1; i < q; ++i) w[i] = (sk[i] / sn - zk[i] / zn) / (2.0 * gamma);
    eta_inv_[k] = 1.0 / eta_[k];
    w0_inv_[k] = 1.0 / (1.0 + w[0]);
  }
  apply(z, lambda);
  return true;
}

void NtScaling::apply(const double* in, double* out) const {
  for (int i = 0; i < cone_.orthant(); ++i) out[i] = w_[i] * in[i];
  for (int k = 0; k < cone_.soc_count(); ++k) {
    const int o = cone_.soc_start(k);
    const int q = cone_.soc_dim(k);
    const double* w = w_.data() + o;
    const double w1u1 = dot(w + 1, in + o + 1, q - 1);
    const double coef = in[o] + w1u1 * w0_inv_[k];
    out[o] = eta_[k] * (w[0] * in[o] + w1u1);
    for (int i = 1; i < q; ++i) out[o + i] = eta_[k] * (in[o + i] + coef * w[i]);
  }
}

void NtScaling::apply_inverse(const double* in, double* out) const {
  for (int i = 0; i < cone_.orthant(); ++i) out[i] = in[i] * w_inv_[i];
  for (int k = 0; k < cone_.soc_count(); ++k) {
    const int o = cone_.soc_start(k);
    apply_inverse_block(cone_.orthant() + k, in + o, out + o, 1);
  }
}

void NtScaling::apply_block(int block, const double* in, double* out, int stride) const {
  if (block < cone_.orthant()) {
    out[0] = w_[block] * in[0];
    return;
  }
  const int k = block - cone_.orthant();
  const int q = cone_.soc_dim(k);
  const double* w = w_.data() + cone_.soc_start(k);
  double w1u1 = 0.0;
  for (int i = 1; i < q; ++i) w1u1 += w[i] * in[i * stride];
  // W u = eta (w0 u0 + w1'u1,  u1 + (u0 + w1'u1/(1+w0)) w1).
  const double coef = in[0] + w1u1 * w0_inv_[k];
  out[0] = eta_[k] * (w[0] * in[0] + w1u1);
  for (int i = 1; i < q; ++i) out[i * stride] = eta_[k] * (in[i * stride] + coef * w[i]);
}

void NtScaling::apply_block_rows(int block, const double* in, double* out, int cols) const {
  if (block < cone_.orthant()) {
    for (int c = 0; c < cols; ++c) out[c] = w_[block] * in[c];
    return;
  }
  const int k = block - cone_.orthant();
  const int q = cone_.soc_dim(k);
  const double* w = w_.data() + cone_.soc_start(k);
  const double eta = eta_[k];
  const double w0_inv = w0_inv_[k];
  // The same formula as apply_block, column by column, with the columns innermost; out's first
  // row holds w1'u1 until the end.
  for (int c = 0; c < cols; ++c) out[c] = 0.0;
  for (int i = 1; i < q; ++i) {
    for (int c = 0; c < cols; ++c) out[c] += w[i] * in[i * cols + c];
  }
  for (int i = 1; i < q; ++i) {
    for (int c = 0; c < cols; ++c) out[i * cols + c] = eta * (in[i * cols + c] + (in[c] + out[c] * w0_inv) * w[i]);
  }
  for (int c = 0; c < cols; ++c) out[c] = eta * (w[0] * in[c] + out[c]);
}

void NtScaling::apply_inverse_block(int block, const double* in, double* out, int stride) const {
  if (block < cone_.orthant()) {
    out[0] = in[0] * w_inv_[block];
    return;
  }
  const int k = block - cone_.orthant();
  const int o = cone_.soc_start(k);
  const int q = cone_.soc_dim(k);
  const double* w = w_.data() + o;
  double w1u1 = 0.0;
  for (int i = 1; i < q; ++i) w1u1 += w[i] * in[i * stride];
  const double inv = eta_inv_[k];
  // W^{-1} u = (1/eta) (w0 u0 - w1'u1,  u1 + (w1'u1/(1+w0) - u0) w1).
  const double coef = w1u1 * w0_inv_[k] - in[0];
  const double head = inv * (w[0] * in[0] - w1u1);
  for (int i = 1; i < q; ++i) out[i * stride] = inv * (in[i * stride] + coef * w[i]);
  out[0] = head;
}

void NtScaling::apply_square_block(int block, const double* in, double* out) const {
  if (block < cone_.orthant()) {
    out[0] = w_[block] * w_[block] * in[0];
    return;
  }
  const int k = block - cone_.orthant();
  const int q = cone_.soc_dim(k);
  const double* w = w_.data() + cone_.soc_start(k);
  const double e2 = eta_[k] * eta_[k];
  const double twice_wu = 2.0 * dot(w, in, q);
  out[0] = e2 * (twice_wu * w[0] - in[0]);
  for (int i = 1; i < q; ++i) out[i] = e2 * (twice_wu * w[i] + in[i]);
}

void NtScaling::apply_inverse_square_block(int block, const double* in, double* out) const {
  if (block < cone_.orthant()) {
    out[0] = in[0] * w_inv_[block] * w_inv_[block];
    return;
  }
  const int k = block - cone_.orthant();
  const int q = cone_.soc_dim(k);
  const double* w = w_.data() + cone_.soc_start(k);
  const double e2 = eta_inv_[k] * eta_inv_[k];
  // Jw = (w0, -w1): (Jw)'u = w0 u0 - w1'u1.
  const double twice_jwu = 2.0 * (w[0] * in[0] - dot(w + 1, in + 1, q - 1));
  out[0] = e2 * (twice_jwu * w[0] - in[0]);
  for (int i = 1; i < q; ++i) out[i] = e2 * (in[i] - twice_jwu * w[i]);
}

void NtScaling::apply_square(const double* in, double* out) const {
  // apply_square_block over every block, with the loop over blocks here so the short per-cone
  // loops are not each a call.
  for (int i = 0; i < cone_.orthant(); ++i) out[i] = w_[i] * w_[i] * in[i];
  for (int k = 0; k < cone_.soc_count(); ++k) {
    const int o = cone_.soc_start(k);
    const int q = cone_.soc_dim(k);
    const double* w = w_.data() + o;
    const double* u = in + o;
    double* v = out + o;
    const double e2 = eta_[k] * eta_[k];
    double wu = 0.0;
    for (int i = 0; i < q; ++i) wu += w[i] * u[i];
    const double twice_wu = 2.0 * wu;
    v[0] = e2 * (twice_wu * w[0] - u[0]);
    for (int i = 1; i < q; ++i) v[i] = e2 * (twice_wu * w[i] + u[i]);
  }
}

}  // namespace visors::optim
