// The library without the command: read a case file, build the model, run its analysis and
// print the result. A nonlinear case (stages) prints where it collapsed, or its factor of safety;
// an elastic one the mean strain of the mass.
//   pull_out CASE.yaml
#include <cstdio>
#include <exception>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/errors.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CASE.yaml\n", argv[0]);
    return 2;
  }
  try {
    const bimrock::Case c = bimrock::read_case_file(argv[1]);
    const bimrock::Model model = bimrock::build_model(c.spec);
    std::printf("%d blocks, %d interfaces\n", model.n_blocks(), model.n_interfaces());
    if (model.stages.empty()) {
      const bimrock::ElasticSolution s = bimrock::solve_elastic(model);
      std::printf("mean strain: xx %.6e, yy %.6e, xy %.6e\n", s.mean_strain(0), s.mean_strain(1),
                  s.mean_strain(2));
      return 0;
    }
    const bimrock::PlasticResult r = bimrock::run_plastic_analysis(model, c.plastic);
    std::printf("%zu increments carried\n", r.history.size());
    if (r.collapse) {
      const bimrock::Stage& stage = model.stages[static_cast<std::size_t>(r.collapse->stage)];
      std::printf("collapse in stage '%s' between load factors %.6f and %.6f\n", stage.name.c_str(),
                  r.collapse->carried, r.collapse->failed);
    }
    if (r.factor_of_safety)
      std::printf("factor of safety at least %.4f\n", r.factor_of_safety->lower);
    return r.stopped ? 5 : 0;
  } catch (const bimrock::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 3;
  }
}
