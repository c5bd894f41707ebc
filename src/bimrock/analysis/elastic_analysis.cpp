#include <bimrock/analysis/elastic_analysis.hpp>

#include <bimrock/analysis/support_check.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

ElasticSolution solve_elastic(const Model& model) {
  const KeptFactorMemoryRelease release_at_end;  // declared first: runs after the factor goes
  ElasticSolution s;
  {
    ScopedTimer t(s.timings, "check supports");
    check_supports(model);
  }
  SparseMatrix k;
  Eigen::VectorXd p;
  {
    ScopedTimer t(s.timings, "assemble");
    SparseMatrix assembled = assemble_stiffness_lower(model);
    k.swap(assembled);  // not an assignment: Eigen 3.4 copies a SparseMatrix assigned
    p = assemble_loads(model, model.loads);
  }
  SparseCholesky cholesky;
  {
    ScopedTimer t(s.timings, "analyze");
    cholesky.analyze(k, 6);
  }
  {
    ScopedTimer t(s.timings, "factorize");
    if (!cholesky.factorize(k))
      report_singular_stiffness(model, cholesky.failed_column());
  }
  s.factor_nonzeros = cholesky.factor_nonzeros();
  {
    ScopedTimer t(s.timings, "solve");
    s.u = cholesky.solve(p);
  }
  {
    ScopedTimer t(s.timings, "evaluate");
    evaluate_fields(model, s);
  }
  return s;
}

void evaluate_fields(const Model& model, ElasticSolution& s, const PlasticParts& plastic) {
  s.blocks.clear();
  s.blocks.reserve(model.blocks.size());
  for (int k = 0; k < model.n_blocks(); ++k)
    s.blocks.push_back(block_state(model, k, s.u, plastic));
  s.interfaces.clear();
  s.interfaces.reserve(model.interfaces.size());
  for (int k = 0; k < model.n_interfaces(); ++k)
    s.interfaces.push_back(interface_state(model, k, s.u, plastic));
  s.mean_strain = mean_strain(model, s.u);
  s.monitor_displacements.clear();
  for (const Monitor& m : model.monitors)
    s.monitor_displacements.push_back(displacement_at(model, m.block, m.point, s.u));
}

}  // namespace bimrock
