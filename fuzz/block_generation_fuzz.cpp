// libFuzzer target: a case's blocks and interfaces, case text -> model (model/model_builder,
// model/block_generation, geometry/*): listed blocks checked, a domain cut by its joint sets and
// joints, Voronoi cells, mesh cells, interfaces, supports and loads. The input is case YAML, so
// the seeds are the examples' cases.
//
// The case's `limits` stay in force, lowered to what one input may take here: a case within them
// must be built in a second or so, so an input that hangs or exhausts memory within them is an
// estimate that missed something (a finding), not a case that asked for much.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/model.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  bimrock::Case c;
  try {
    c = bimrock::read_case_string(text, bimrock::fuzz::case_name());
  } catch (const bimrock::InputError&) {
    return -1;  // the reader's target covers it; keep this corpus to cases that read
  }
  bimrock::CaseLimits& l = c.spec.limits;
  l.blocks = std::min(l.blocks, 5e3);
  l.joint_traces = std::min(l.joint_traces, 2e3);
  l.interfaces = std::min(l.interfaces, 5e4);
  l.yield_planes = std::min(l.yield_planes, 1e5);
  l.increments = std::min(l.increments, 1e4);
  try {
    static_cast<void>(bimrock::build_model(c.spec));
  } catch (const bimrock::InputError& e) {
    bimrock::fuzz::expect_located(e);
  } catch (const bimrock::ModelError&) {
  }
  return 0;
}
