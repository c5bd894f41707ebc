#pragma once
/// @file The terms K is the sum of (eq. 14), handed one by one to whatever assembles them: the
/// lower triangle of the whole K (global_system.hpp), or a process's rows of K in the PETSc
/// backend (petsc/distributed_stiffness.hpp). What K holds is decided here, once.
#include <bimrock/assembly/local_stiffness.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {

/// Receives the terms of K from add_stiffness_terms().
class StiffnessSink {
 public:
  virtual ~StiffnessSink() = default;
  /// Whether the terms on `block` are wanted: a term on none of the wanted blocks is neither
  /// computed nor handed over.
  [[nodiscard]] virtual bool wants(int block) const = 0;
  /// A term on one block's six unknowns: its elastic stiffness, a support's, or the decoupling
  /// diagonal of an absent block.
  virtual void add(const Mat6& local, int block) = 0;
  /// A term coupling two blocks (an interface, a bolt's spring), on [d_i; d_j].
  virtual void add(const Mat12& local, int block_i, int block_j) = 0;

 protected:
  StiffnessSink() = default;
  StiffnessSink(const StiffnessSink&) = default;
  StiffnessSink& operator=(const StiffnessSink&) = default;
};

/// Hands `sink` every term of K of what stands (`present`): each block's stiffness (an absent
/// block's six unknowns held by a decoupled diagonal instead, so that its displacement stays
/// what it was), each support's, each interface's between two present blocks and each present
/// bolt spring's.
void add_stiffness_terms(const Model& model, const Presence& present, StiffnessSink& sink);

}  // namespace bimrock
