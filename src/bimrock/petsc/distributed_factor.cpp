#include <bimrock/petsc/distributed_factor.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <bimrock/analysis/support_check.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/petsc/owned.hpp>
#include <bimrock/petsc/petsc_call.hpp>

namespace bimrock {
namespace {

constexpr int kBlock = 6;  // unknowns per block
// Right-hand sides are solved and gathered in groups of at most this many values in all (a
// gathered group is held by every process).
constexpr std::int64_t kGatheredValues = std::int64_t{1} << 25;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Every process runs the same analysis on the same data, so each call of the factor comes from
// all of them with the same arguments. Were they to differ (a bug), the processes would part
// ways, each waiting forever on the others in MUMPS; the arguments' fingerprint is compared at
// each call instead, and all of them stop with an internal error.
void check_same_on_every_process(const char* call, const std::array<double, 3>& fingerprint) {
  std::array<double, 6> local{};
  for (std::size_t i = 0; i < fingerprint.size(); ++i) {
    local[i] = fingerprint[i];
    local[i + 3] = -fingerprint[i];
  }
  std::array<double, 6> highest{};
  MPI_Allreduce(local.data(), highest.data(), 6, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  for (std::size_t i = 0; i < fingerprint.size(); ++i)
    if (!(highest[i] == -highest[i + 3]))  // false for a NaN too
      throw std::logic_error(std::string(call) +
                             ": the processes of the MPI run asked for different things "
                             "(their analyses have parted ways)");
}

// MUMPS's Cholesky (LDL^T where `k` is not flagged positive definite) factor of `k` into
// `factor`, with the unknowns of `schur` (if any) last and their Schur complement kept; false
// where the factorization fails (K singular).
bool factorize_with_mumps(Mat k, IS schur, Mat* factor) {
  petsc_call(MatGetFactor(k, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, factor), "MatGetFactor");
  if (schur != nullptr)
    petsc_call(MatFactorSetSchurIS(*factor, schur), "MatFactorSetSchurIS");
  MatFactorInfo info;
  petsc_call(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
  petsc_call(MatCholeskyFactorSymbolic(*factor, k, nullptr, &info), "MatCholeskyFactorSymbolic");
  petsc_call(MatCholeskyFactorNumeric(*factor, k, &info), "MatCholeskyFactorNumeric");
  MatFactorError error = MAT_FACTOR_NOERROR;
  petsc_call(MatFactorGetError(*factor, &error), "MatFactorGetError");
  return error == MAT_FACTOR_NOERROR;
}

// Solves with K's MUMPS factor for right-hand sides given (and answered) on every process in
// the model's numbering.
class MumpsSolver final : public SpdSolver {
 public:
  MumpsSolver(std::shared_ptr<const BlockPartition> partition, Mat k)
      : partition_(std::move(partition)), k_(k) {
    int ranks = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
    const int mine = static_cast<int>(partition_->mine.rows());
    rows_of_.resize(static_cast<std::size_t>(ranks));
    MPI_Allgather(&mine, 1, MPI_INT, rows_of_.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  }

  [[nodiscard]] bool factorize() {
    const auto start = std::chrono::steady_clock::now();
    const bool ok = factorize_with_mumps(k_, nullptr, factor_.out());
    work_.factorize_seconds += seconds_since(start);
    ++work_.factorizations;
    if (ok) {
      // MUMPS's count of the factor's entries, over every process (negative: in millions).
      PetscInt entries = 0;
      petsc_call(MatMumpsGetInfog(factor_.get(), 29, &entries), "MatMumpsGetInfog");
      nonzeros_ = entries < 0 ? -std::int64_t{entries} * 1000000 : std::int64_t{entries};
    }
    return ok;
  }

  [[nodiscard]] std::int64_t rows() const override {
    return kBlock * static_cast<std::int64_t>(partition_->block.size());
  }
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    return solve(Eigen::MatrixXd(b)).col(0);
  }
  [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override {
    check_same_on_every_process("a solve with K",
                                {static_cast<double>(b.cols()), b.sum(), b.squaredNorm()});
    const auto start = std::chrono::steady_clock::now();
    Eigen::MatrixXd x(b.rows(), b.cols());
    const Eigen::Index group = std::max<Eigen::Index>(
        1, static_cast<Eigen::Index>(kGatheredValues / std::max<Eigen::Index>(1, b.rows())));
    for (Eigen::Index first = 0; first < b.cols(); first += group) {
      const Eigen::Index columns = std::min(group, b.cols() - first);
      x.middleCols(first, columns) = solve_group(b.middleCols(first, columns));
    }
    work_.solve_seconds += seconds_since(start);
    work_.solved_columns += b.cols();
    return x;
  }
  [[nodiscard]] std::int64_t factor_nonzeros() const override { return nonzeros_; }
  [[nodiscard]] const CholeskyWork& work() const override { return work_; }

 private:
  // Scatters b's rows to their processes, solves, and gathers x to every process.
  [[nodiscard]] Eigen::MatrixXd solve_group(const Eigen::MatrixXd& b) const {
    const BlockPartition& p = *partition_;
    const auto mine = static_cast<PetscInt>(p.mine.rows());
    const auto columns = static_cast<PetscInt>(b.cols());
    Owned<Mat, MatDestroy> rhs;
    Owned<Mat, MatDestroy> solution;
    petsc_call(MatCreateDense(PETSC_COMM_WORLD, mine, PETSC_DECIDE, static_cast<PetscInt>(rows()),
                              columns, nullptr, rhs.out()),
               "MatCreateDense");
    {
      PetscScalar* v = nullptr;
      PetscInt lda = 0;
      petsc_call(MatDenseGetLDA(rhs.get(), &lda), "MatDenseGetLDA");
      petsc_call(MatDenseGetArrayWrite(rhs.get(), &v), "MatDenseGetArrayWrite");
      for (PetscInt c = 0; c < columns; ++c)
        for (std::int64_t n = p.mine.first; n < p.mine.last; ++n)
          for (int d = 0; d < kBlock; ++d)
            v[c * lda + kBlock * (n - p.mine.first) + d] =
                b(kBlock * p.block[static_cast<std::size_t>(n)] + d, c);
      petsc_call(MatDenseRestoreArrayWrite(rhs.get(), &v), "MatDenseRestoreArrayWrite");
    }
    petsc_call(MatDuplicate(rhs.get(), MAT_DO_NOT_COPY_VALUES, solution.out()), "MatDuplicate");
    petsc_call(MatMatSolve(factor_.get(), rhs.get(), solution.get()), "MatMatSolve");
    // Every process's rows, column by column, gathered to every process: the ranges in rank
    // order are the partition's numbering.
    std::vector<double> local(static_cast<std::size_t>(mine) * static_cast<std::size_t>(columns));
    {
      const PetscScalar* v = nullptr;
      PetscInt lda = 0;
      petsc_call(MatDenseGetLDA(solution.get(), &lda), "MatDenseGetLDA");
      petsc_call(MatDenseGetArrayRead(solution.get(), &v), "MatDenseGetArrayRead");
      for (PetscInt c = 0; c < columns; ++c)
        std::copy(v + c * lda, v + c * lda + mine, local.begin() + c * mine);
      petsc_call(MatDenseRestoreArrayRead(solution.get(), &v), "MatDenseRestoreArrayRead");
    }
    std::vector<int> counts(rows_of_.size());
    std::vector<int> offsets(rows_of_.size(), 0);
    for (std::size_t r = 0; r < rows_of_.size(); ++r) {
      counts[r] = rows_of_[r] * static_cast<int>(columns);
      if (r > 0)
        offsets[r] = offsets[r - 1] + counts[r - 1];
    }
    std::vector<double> all(static_cast<std::size_t>(rows()) * static_cast<std::size_t>(columns));
    MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_DOUBLE, all.data(),
                   counts.data(), offsets.data(), MPI_DOUBLE, PETSC_COMM_WORLD);
    Eigen::MatrixXd x(b.rows(), b.cols());
    std::int64_t row = 0;  // the first row of rank r's range, in the partition's numbering
    for (std::size_t r = 0; r < rows_of_.size(); ++r) {
      for (PetscInt c = 0; c < columns; ++c)
        for (int i = 0; i < rows_of_[r]; ++i) {
          const std::int64_t n = (row + i) / kBlock;
          x(kBlock * p.block[static_cast<std::size_t>(n)] + (row + i) % kBlock, c) =
              all[static_cast<std::size_t>(offsets[r] + c * rows_of_[r] + i)];
        }
      row += rows_of_[r];
    }
    return x;
  }

  std::shared_ptr<const BlockPartition> partition_;
  Mat k_;
  Owned<Mat, MatDestroy> factor_;
  std::vector<int> rows_of_;  // per process, its rows of K
  std::int64_t nonzeros_ = 0;
  mutable CholeskyWork work_;
};

class DistributedFactor final : public StiffnessFactor {
 public:
  DistributedFactor(const Model& model, std::shared_ptr<const BlockPartition> partition,
                    const Presence& present, const SparseMatrix& lower)
      : model_(model), partition_(std::move(partition)), lower_(lower) {
    *k_.out() = assemble_distributed_stiffness(model, *partition_, present);
    solver_ = std::make_unique<MumpsSolver>(partition_, k_.get());
    if (!solver_->factorize()) {
      // CHOLMOD names the column where K breaks down, and the block left free with it.
      CholmodStiffnessFactor named(lower);
      if (!named.factorize())
        report_singular_stiffness(model, named.failed_column());
      throw ModelError(
          "MUMPS found K of the blocks present singular, where CHOLMOD does not: "
          "run without --solver petsc",
          {});
    }
  }

  [[nodiscard]] const SpdSolver& solver() const override { return *solver_; }
  [[nodiscard]] std::unique_ptr<CondensedStiffness> condense(
      const CondensedStiffness& /*whole*/, const std::vector<char>& region) override {
    return std::make_unique<CondensedStiffness>(
        region, condense_onto_region(model_, *partition_, k_.get(), lower_, region));
  }
  [[nodiscard]] SparseCholesky* reorderable() override { return nullptr; }

 private:
  const Model& model_;
  std::shared_ptr<const BlockPartition> partition_;
  const SparseMatrix& lower_;
  Owned<Mat, MatDestroy> k_;
  std::unique_ptr<MumpsSolver> solver_;
};

}  // namespace

SparseMatrix condense_onto_region(const Model& model, const BlockPartition& partition, Mat k,
                                  const SparseMatrix& lower, const std::vector<char>& region) {
  const auto blocks = static_cast<std::size_t>(model.n_blocks());
  {
    double count = 0.0;
    double sum = 0.0;
    for (std::size_t b = 0; b < region.size(); ++b)
      if (region[b]) {
        count += 1.0;
        sum += static_cast<double>(b);
      }
    check_same_on_every_process("a condensation onto a region", {count, sum, 0.0});
  }
  const auto in = [&](std::int64_t unknown) {
    return region[static_cast<std::size_t>(unknown / kBlock)] != 0;
  };
  // The boundary B: the region's blocks with a term of K shared with a block outside it.
  std::vector<char> boundary(blocks, 0);
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
      if (in(it.row()) != in(j))
        boundary[static_cast<std::size_t>((in(j) ? j : it.row()) / kBlock)] = 1;
  // The region's unknowns in its blocks' ascending order; B's among them by their number in the
  // partition (the order of the Schur complement MUMPS returns).
  std::vector<std::int64_t> local(blocks, -1);           // per block of the region, its place
  std::vector<std::pair<PetscInt, std::int64_t>> schur;  // (number in K, place in S_R)
  std::vector<PetscInt> interior;                        // this process's rows of R's interior
  std::int64_t places = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    if (!region[b])
      continue;
    local[b] = places++;
    const std::int64_t number = partition.number[b];
    for (int d = 0; d < kBlock; ++d) {
      const auto row = static_cast<PetscInt>(kBlock * number + d);
      if (boundary[b])
        schur.emplace_back(row, kBlock * local[b] + d);
      else if (partition.mine.owns(number))
        interior.push_back(row);
    }
  }
  std::sort(schur.begin(), schur.end());
  const auto nb = static_cast<Eigen::Index>(schur.size());

  // S_BB from K with the interior decoupled, factorized by MUMPS with B last (a region without
  // a boundary, the whole model, is K itself: nothing to factorize).
  Eigen::MatrixXd s_bb(nb, nb);
  if (nb > 0) {
    Owned<Mat, MatDestroy> decoupled;
    petsc_call(MatDuplicate(k, MAT_COPY_VALUES, decoupled.out()), "MatDuplicate");
    petsc_call(MatZeroRowsColumns(decoupled.get(), static_cast<PetscInt>(interior.size()),
                                  interior.data(), 1.0, nullptr, nullptr),
               "MatZeroRowsColumns");
    // Factorized as symmetric (LDL^T), not as positive definite: MUMPS's positive definite mode
    // returns only the diagonal of a Schur complement centralized on the first of several
    // processes (PETSc 3.18, MUMPS 5.5; DistributedFactor.CondensesARegionAsEliminationDoes
    // fails with it under mpirun -n 2).
    petsc_call(MatSetOption(decoupled.get(), MAT_SPD, PETSC_FALSE), "MatSetOption(MAT_SPD)");
    petsc_call(MatSetOption(decoupled.get(), MAT_SYMMETRIC, PETSC_TRUE),
               "MatSetOption(MAT_SYMMETRIC)");
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    std::vector<PetscInt> numbers;
    if (rank == 0)  // MUMPS returns S_BB to the first process, which names B
      for (const auto& [number, place] : schur)
        numbers.push_back(number);
    Owned<IS, ISDestroy> is;
    petsc_call(ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(numbers.size()),
                               numbers.data(), PETSC_COPY_VALUES, is.out()),
               "ISCreateGeneral");
    Owned<Mat, MatDestroy> factor;
    if (!factorize_with_mumps(decoupled.get(), is.get(), factor.out()))
      throw std::logic_error("condense_onto_region: K, positive definite before, is not now");
    Owned<Mat, MatDestroy> s;
    MatFactorSchurStatus status = MAT_FACTOR_SCHUR_UNFACTORED;
    petsc_call(MatFactorCreateSchurComplement(factor.get(), s.out(), &status),
               "MatFactorCreateSchurComplement");
    if (rank == 0) {
      const PetscScalar* v = nullptr;
      PetscInt lda = 0;
      petsc_call(MatDenseGetLDA(s.get(), &lda), "MatDenseGetLDA");
      petsc_call(MatDenseGetArrayRead(s.get(), &v), "MatDenseGetArrayRead");
      for (Eigen::Index c = 0; c < nb; ++c)
        std::copy(v + c * lda, v + c * lda + nb, s_bb.col(c).data());
      petsc_call(MatDenseRestoreArrayRead(s.get(), &v), "MatDenseRestoreArrayRead");
    }
    for (Eigen::Index c = 0; c < nb; ++c)
      MPI_Bcast(s_bb.col(c).data(), static_cast<int>(nb), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  }

  // S_R: K_RR's lower triangle, its B x B block replaced by S_BB's.
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  const auto place = [&](std::int64_t unknown) {
    return kBlock * local[static_cast<std::size_t>(unknown / kBlock)] + unknown % kBlock;
  };
  const auto on_boundary = [&](std::int64_t unknown) {
    return boundary[static_cast<std::size_t>(unknown / kBlock)] != 0;
  };
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j)
    if (in(j))
      for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
        if (in(it.row()) && !(on_boundary(it.row()) && on_boundary(j)))
          entries.emplace_back(place(it.row()), place(j), it.value());
  for (Eigen::Index q = 0; q < nb; ++q)
    for (Eigen::Index p = 0; p < nb; ++p) {
      const std::int64_t row = schur[static_cast<std::size_t>(p)].second;
      const std::int64_t column = schur[static_cast<std::size_t>(q)].second;
      if (row >= column)  // read from S_BB's lower triangle, in MUMPS's order
        entries.emplace_back(row, column, p >= q ? s_bb(p, q) : s_bb(q, p));
    }
  SparseMatrix s(kBlock * places, kBlock * places);
  s.setFromTriplets(entries.begin(), entries.end());
  return s;
}

StiffnessFactorization distributed_factorization(const Model& model) {
  auto partition = std::make_shared<const BlockPartition>(partition_blocks(model));
  return [&model, partition](const Presence& present,
                             const SparseMatrix& lower) -> std::unique_ptr<StiffnessFactor> {
    return std::make_unique<DistributedFactor>(model, partition, present, lower);
  };
}

}  // namespace bimrock
