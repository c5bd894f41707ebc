#pragma once
/// @file Internal to SparseCholesky (not part of the public API): the CHOLMOD state its member
/// functions share, and the views of Eigen's matrices that CHOLMOD reads. The class is one
/// interface over several concepts, one file each: sparse_cholesky.cpp (analysis, numeric
/// factorization and solves), block_ordering.cpp (the fill-reducing order of the graph of
/// blocks), zone_ordering.cpp (the factor's order by nested zones, analyze_last) and
/// zone_schur_complement.cpp (a zone's Schur complement read from the factor's trailing block).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include <cholmod.h>

#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock::cholesky {

/// Frees a vector's memory (`v = {}` keeps its capacity: it assigns an empty initializer list).
template <class Vector>
void release(Vector& v) {
  Vector().swap(v);
}

/// A cholmod view of the Eigen matrix (no copy): stype -1 reads the lower triangle.
inline cholmod_sparse view(const CholmodMatrix& a) {
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

/// A cholmod view of the dense Eigen matrix (no copy).
inline cholmod_dense view(const Eigen::MatrixXd& b) {
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

/// The lower-triangular pattern of the graph of block_size x block_size blocks of `lower`.
[[nodiscard]] CholmodMatrix block_pattern(const CholmodMatrix& lower, int block_size);

/// The permutation of the unknowns that orders whole blocks of block_size as `coarse` does.
[[nodiscard]] std::vector<std::int64_t> expand_blocks(const std::vector<std::int64_t>& coarse,
                                                      int block_size);

}  // namespace bimrock::cholesky

namespace bimrock {

struct SparseCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  // A supernodal factor in a fill-reducing order takes tril(P A P^T); from a lower triangle
  // CHOLMOD builds it with two transposes per factorization (cholmod_factorize_p), a sizeable
  // part of a factorization's time on the main thread.
  // From the second factorization of one analysis on, the matrix is scattered into that form
  // here, in one pass, and factorized as if its order were natural.
  std::int64_t factorizations_since_analysis = 0;
  // analyze_last() builds that form at once and analyzes it in natural order: the analysis
  // costs the same (CHOLMOD's four transposes give way to the permutation), and the first
  // factorization reads it without CHOLMOD's transposes, then frees it (K and a region's S are
  // factorized once per analysis).
  std::vector<std::int64_t> permuted_p;  // tril(P A P^T): column starts, rows, values
  std::vector<std::int64_t> permuted_i;
  std::vector<double> permuted_x;
  std::vector<std::int64_t> scatter;  // entry k of the caller's lower -> permuted_x (-1: above)
  // The analyzed pattern's checksum: a matrix of another one is refused (CHOLMOD would
  // factorize it without notice, into a wrong factor).
  std::uint64_t analyzed_pattern = 0;

  void release_permuted() {
    cholesky::release(scatter);
    cholesky::release(permuted_p);
    cholesky::release(permuted_i);
    cholesky::release(permuted_x);
  }

  Impl() {
    cholmod_l_start(&common);
    common.print = 0;  // we report failures ourselves
  }
  ~Impl() {
    if (factor)
      cholmod_l_free_factor(&factor, &common);
    cholmod_l_finish(&common);
  }
};

}  // namespace bimrock
