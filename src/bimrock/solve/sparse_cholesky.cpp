#include <bimrock/solve/sparse_cholesky.hpp>

#include <chrono>
#include <stdexcept>
#include <vector>

#include <cholmod.h>

namespace bimrock {

struct SparseCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;

  Impl() {
    cholmod_l_start(&common);
    common.print = 0;  // we report failures ourselves
  }
  ~Impl() {
    if (factor)
      cholmod_l_free_factor(&factor, &common);
    cholmod_l_finish(&common);
  }

  // A cholmod view of the Eigen matrix (no copy): stype -1 reads the lower triangle.
  static cholmod_sparse view(const CholmodMatrix& a) {
    cholmod_sparse s{};
    s.nrow = static_cast<size_t>(a.rows());
    s.ncol = static_cast<size_t>(a.cols());
    s.nzmax = static_cast<size_t>(a.nonZeros());
    s.p = const_cast<std::int64_t*>(a.outerIndexPtr());
    s.i = const_cast<std::int64_t*>(a.innerIndexPtr());
    s.x = const_cast<double*>(a.valuePtr());
    s.stype = -1;
    s.itype = CHOLMOD_LONG;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }

  static cholmod_dense view(const Eigen::MatrixXd& b) {
    cholmod_dense d{};
    d.nrow = static_cast<size_t>(b.rows());
    d.ncol = static_cast<size_t>(b.cols());
    d.nzmax = d.nrow * d.ncol;
    d.d = d.nrow;
    d.x = const_cast<double*>(b.data());
    d.xtype = CHOLMOD_REAL;
    d.dtype = CHOLMOD_DOUBLE;
    return d;
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The lower-triangular pattern of the graph of block_size x block_size blocks of `lower`.
CholmodMatrix block_pattern(const CholmodMatrix& lower, int block_size) {
  const std::int64_t nb = lower.rows() / block_size;
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  std::vector<std::int64_t> seen(static_cast<std::size_t>(nb), -1);
  for (std::int64_t kb = 0; kb < nb; ++kb) {
    for (std::int64_t c = kb * block_size; c < (kb + 1) * block_size; ++c) {
      for (CholmodMatrix::InnerIterator it(lower, c); it; ++it) {
        const std::int64_t rb = it.row() / block_size;
        if (rb >= kb && seen[rb] != kb) {
          seen[rb] = kb;
          entries.emplace_back(rb, kb, 1.0);
        }
      }
    }
  }
  CholmodMatrix pattern(nb, nb);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  return pattern;
}

}  // namespace

void SparseCholesky::analyze(const CholmodMatrix& lower, int block_size) {
  if (!lower.isCompressed())
    throw std::logic_error("SparseCholesky: matrix must be compressed");
  if (impl_->factor)
    cholmod_l_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse a = Impl::view(lower);
  cholmod_common& cm = impl_->common;
  if (block_size > 1 && lower.rows() % block_size == 0 && lower.rows() > block_size) {
    // Order the block graph with CHOLMOD's default strategy, expand the permutation to the
    // unknowns, and analyze the full matrix with that given ordering.
    const CholmodMatrix pattern = block_pattern(lower, block_size);
    cholmod_sparse p = Impl::view(pattern);
    cholmod_factor* coarse = cholmod_l_analyze(&p, &cm);
    if (!coarse)
      throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
    const auto* coarse_perm = static_cast<const std::int64_t*>(coarse->Perm);
    std::vector<std::int64_t> perm(static_cast<std::size_t>(lower.rows()));
    for (std::int64_t k = 0; k < pattern.rows(); ++k)
      for (int d = 0; d < block_size; ++d)
        perm[block_size * k + d] = block_size * coarse_perm[k] + d;
    cholmod_l_free_factor(&coarse, &cm);
    const int saved_nmethods = cm.nmethods;
    const int saved_ordering = cm.method[0].ordering;
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    impl_->factor = cholmod_l_analyze_p(&a, perm.data(), nullptr, 0, &cm);
    cm.nmethods = saved_nmethods;
    cm.method[0].ordering = saved_ordering;
  } else {
    impl_->factor = cholmod_l_analyze(&a, &cm);
  }
  if (!impl_->factor)
    throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
  n_ = lower.rows();
  analyzed_nonzeros_ = lower.nonZeros();
  factor_flops_ = cm.fl;
  factorized_ = false;
}

bool SparseCholesky::factorize(const CholmodMatrix& lower) {
  if (!impl_->factor)
    analyze(lower);
  cholmod_sparse a = Impl::view(lower);
  const auto start = std::chrono::steady_clock::now();
  cholmod_l_factorize(&a, impl_->factor, &impl_->common);
  ++work_.factorizations;
  work_.factorize_seconds += seconds_since(start);
  if (impl_->common.status == CHOLMOD_OUT_OF_MEMORY)
    throw std::runtime_error("CHOLMOD factorize: out of memory");
  const auto minor = static_cast<std::int64_t>(impl_->factor->minor);
  if (impl_->common.status == CHOLMOD_NOT_POSDEF || minor < n_) {
    const auto* perm = static_cast<const std::int64_t*>(impl_->factor->Perm);
    failed_column_ = perm ? perm[minor] : minor;
    factorized_ = false;
    return false;
  }
  // A small matrix gets a simplicial LDL' factor, which does not fail where the matrix is not
  // positive definite: its D must be checked (the reduced tangent relies on the refusal).
  const cholmod_factor* f = impl_->factor;
  if (!f->is_super && !f->is_ll) {
    const auto* p = static_cast<const std::int64_t*>(f->p);
    const auto* x = static_cast<const double*>(f->x);
    for (std::int64_t j = 0; j < n_; ++j)
      if (!(x[p[j]] > 0.0)) {
        const auto* perm = static_cast<const std::int64_t*>(f->Perm);
        failed_column_ = perm ? perm[j] : j;
        factorized_ = false;
        return false;
      }
  }
  failed_column_ = -1;
  factorized_ = true;
  return true;
}

std::int64_t SparseCholesky::factor_nonzeros() const {
  if (!impl_->factor)
    return 0;
  cholmod_factor* f = impl_->factor;
  if (f->is_super)
    return static_cast<std::int64_t>(f->xsize);
  return static_cast<std::int64_t>(f->nzmax);
}

bool SparseCholesky::supernodal() const {
  return impl_->factor && impl_->factor->is_super;
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const {
  if (!factorized_)
    throw std::logic_error("SparseCholesky::solve before a successful factorize");
  cholmod_dense rhs = Impl::view(b);
  const auto start = std::chrono::steady_clock::now();
  cholmod_dense* x = cholmod_l_solve(CHOLMOD_A, impl_->factor, &rhs, &impl_->common);
  work_.solved_columns += b.cols();
  work_.solve_seconds += seconds_since(start);
  if (!x)
    throw std::runtime_error("CHOLMOD solve failed");
  Eigen::MatrixXd out =
      Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), b.rows(), b.cols());
  cholmod_l_free_dense(&x, &impl_->common);
  return out;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::MatrixXd m = b;
  return solve(m).col(0);
}

}  // namespace bimrock
