// bimrock._core: the library's cases, analyses and results for Python (docs/python.md). The
// package bimrock (python/bimrock/__init__.py) wraps it; the user's API is there.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <yaml-cpp/yaml.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/mechanism_blocks.hpp>
#include <bimrock/analysis/memory_estimate.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/output_folder.hpp>
#include <bimrock/io/results_writer.hpp>
#include <bimrock/solve/factor_memory.hpp>

namespace py = pybind11;

namespace bimrock::python {

namespace {

using Array = py::array_t<double>;

Array matrix(std::size_t rows, std::size_t cols) {
  return Array({rows, cols});
}

// The InputError of a case made from a document (a dict, or a file's document changed): its line
// is one of the text the document was written to, which the user never saw, so it is left out;
// the item path names the place.
[[noreturn]] void rethrow_without_line(const InputError& e) {
  throw InputError(e.file(), 0, e.item(), e.message());
}

// Digits with an optional sign: a YAML integer as the case reader reads one.
bool is_integer(const std::string& s) {
  const std::size_t start = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  return s.size() > start && std::all_of(s.begin() + static_cast<std::ptrdiff_t>(start), s.end(),
                                         [](char ch) { return ch >= '0' && ch <= '9'; });
}

// A YAML document as Python data, scalars typed as the case reader types them: a quoted scalar
// is text; a plain one is an int, a float, true / false or null when it reads as one, else text.
py::object to_python(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict d;
      for (const auto& kv : node)
        d[to_python(kv.first)] = to_python(kv.second);
      return py::object(std::move(d));
    }
    case YAML::NodeType::Sequence: {
      py::list l;
      for (const auto& v : node)
        l.append(to_python(v));
      return py::object(std::move(l));
    }
    case YAML::NodeType::Scalar: {
      const std::string& s = node.Scalar();
      if (node.Tag() == "!")  // quoted
        return py::str(s);
      // The spellings the reader takes for true / false (yes, on, ...), but not y and n, more
      // likely a name.
      bool b = false;
      if (s.size() > 1 && YAML::convert<bool>::decode(node, b))
        return py::bool_(b);
      if (s == "~" || s == "null")
        return py::none();
      if (is_integer(s))
        return py::module_::import("builtins").attr("int")(s);
      double x = 0.0;
      if (YAML::convert<double>::decode(node, x) && std::isfinite(x))
        return py::float_(x);
      return py::str(s);
    }
    default:
      return py::none();
  }
}

struct Increment {
  int carried = 0;  // 1-based count of carried increments
  IncrementRecord record;
  std::optional<AnalysisState> state;  // kept where the results folder has a step of it
};

// The results of one analysis of a case, with what write() needs to write the folder the
// command writes.
struct Result {
  std::shared_ptr<const Model> model;
  std::shared_ptr<const Case> c;
  ElasticSolution fields;  // the final state's blocks, interfaces, monitors, mean strain
  std::optional<PlasticResult> plastic;
  std::vector<Increment> increments;  // nonlinear: every carried increment

  void write(const std::string& folder) const {
    const std::filesystem::path out(folder);
    check_output_folder(out);
    if (!plastic) {
      write_elastic_results(*model, fields, c->output, out);
      return;
    }
    PlasticResultsWriter writer(*model, c->output, out);
    // The writer sees every carried increment, in order; it keeps the states of those it
    // writes, which are the ones kept here (the others are passed the last state kept: the
    // writer only holds it as its latest until a later one comes).
    const AnalysisState* last = nullptr;
    for (const Increment& i : increments) {
      if (i.state)
        last = &*i.state;
      writer.on_increment(i.record, last ? *last : plastic->state);
    }
    (void)writer.finish(*plastic);
  }
};

// A case read and its model built: the geometry once, the materials and loads again on a
// rebuild.
struct CaseModel {
  std::shared_ptr<const Case> c;
  std::shared_ptr<const Model> model;
  bool lines = true;

  static CaseModel read(const std::string& text, const std::string& name, bool lines,
                        const CaseModel* geometry) {
    try {
      auto c = std::make_shared<const Case>(read_case_string(text, name));
      auto model = std::make_shared<const Model>(geometry ? rebuild_model(*geometry->model, c->spec)
                                                          : build_model(c->spec));
      return {std::move(c), std::move(model), lines};
    } catch (const InputError& e) {
      if (!lines)
        rethrow_without_line(e);
      throw;
    }
  }

  static CaseModel file(const std::string& path) {
    auto c = std::make_shared<const Case>(read_case_file(path));
    auto model = std::make_shared<const Model>(build_model(c->spec));
    return {std::move(c), std::move(model), true};
  }

  py::dict check() const {
    const Model& m = *model;
    int supports = 0;
    for (const Interface& f : m.interfaces)
      supports += f.is_support() ? 1 : 0;
    const MemoryEstimate e = estimate_memory(m);
    py::dict d;
    d["blocks"] = m.n_blocks();
    d["interfaces"] = m.n_interfaces() - supports;
    d["support_interfaces"] = supports;
    d["unknowns"] = m.n_dofs();
    d["stages"] = m.stages.size();
    d["analysis"] = m.stages.empty() ? "elastic" : "nonlinear";
    d["memory_estimate_bytes"] = e.peak_bytes;
    try {
      bimrock::check_output_size(m, *c);
    } catch (const InputError& err) {
      if (!lines)
        rethrow_without_line(err);
      throw;
    }
    return d;
  }

  // progress(info) after each carried increment, with the GIL; it may raise (a KeyboardInterrupt
  // from Ctrl-C among them: the signal is checked there), which ends the analysis by unwinding
  // it and is raised again from run().
  Result run(const std::optional<py::function>& progress) const {
    Result r{model, c, {}, std::nullopt, {}};
    if (PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    if (model->stages.empty()) {
      {
        const py::gil_scoped_release release;
        r.fields = solve_elastic(*model);
      }
      if (PyErr_CheckSignals() != 0)
        throw py::error_already_set();
      return r;
    }
    const int every = c->output.vtk ? std::max(1, c->output.vtk_every) : 0;
    const auto on_increment = [&](const IncrementRecord& record, const AnalysisState& state) {
      const py::gil_scoped_acquire acquire;
      Increment i{static_cast<int>(r.increments.size()) + 1, record, std::nullopt};
      if (every > 0 && i.carried % every == 0)
        i.state = state;
      r.increments.push_back(std::move(i));
      if (progress) {
        const Stage& stage = model->stages[static_cast<std::size_t>(record.stage)];
        py::dict info;
        info["stage"] = record.stage;
        info["stage_name"] = stage.name;
        info["increment"] = record.increment;
        info["increments"] = stage.increments;
        info["stage_factor"] = record.stage_factor;
        info["seconds"] = record.seconds;
        (*progress)(info);
      }
      if (PyErr_CheckSignals() != 0)
        throw py::error_already_set();
    };
    // The factor of safety's search: one call per F carried, as a stage named "factor of
    // safety" after the case's stages, its stage_factor F.
    int trials = 0;
    auto last = std::chrono::steady_clock::now();
    const auto on_trial = [&](const FactorTrial& t) {
      const auto now = std::chrono::steady_clock::now();
      const py::gil_scoped_acquire acquire;
      if (progress) {
        py::dict info;
        info["stage"] = model->stages.size();
        info["stage_name"] = "factor of safety";
        info["increment"] = ++trials;
        info["increments"] = py::none();
        info["stage_factor"] = t.factor;
        info["seconds"] = std::chrono::duration<double>(now - last).count();
        (*progress)(info);
      }
      last = now;
      if (PyErr_CheckSignals() != 0)
        throw py::error_already_set();
    };
    PlasticResult p;
    {
      const py::gil_scoped_release release;
      p = run_plastic_analysis(*model, c->plastic, on_increment, {}, on_trial);
    }
    // The last carried state, kept for the folder's last step whatever the thinning.
    if (every > 0 && !r.increments.empty() && !r.increments.back().state)
      r.increments.back().state = p.state;
    YieldPointIndex index;
    (void)make_yield_points(*model, &index);
    r.fields.u = p.state.u;
    evaluate_fields(*model, r.fields, {&index, &p.state.points});
    r.fields.timings = p.timings;
    r.plastic = std::move(p);
    return r;
  }
};

py::array_t<std::int64_t> int_matrix(std::size_t rows, std::size_t cols) {
  return py::array_t<std::int64_t>({rows, cols});
}

py::dict blocks_of(const Result& r) {
  const Model& m = *r.model;
  const auto n = static_cast<std::size_t>(m.n_blocks());
  Array centroids = matrix(n, 2), unknowns = matrix(n, 6), strains = matrix(n, 3),
        stresses = matrix(n, 3), plastic = matrix(n, 3);
  Array areas(n);
  py::array_t<std::int64_t> material(n);
  auto c = centroids.mutable_unchecked<2>();
  auto d = unknowns.mutable_unchecked<2>();
  auto e = strains.mutable_unchecked<2>();
  auto s = stresses.mutable_unchecked<2>();
  auto p = plastic.mutable_unchecked<2>();
  auto a = areas.mutable_unchecked<1>();
  auto mat = material.mutable_unchecked<1>();
  for (std::size_t k = 0; k < n; ++k) {
    const Block& b = m.blocks[k];
    const BlockState& st = r.fields.blocks[k];
    c(k, 0) = b.centroid.x();
    c(k, 1) = b.centroid.y();
    a(k) = b.area;
    mat(k) = b.material;
    for (int i = 0; i < 6; ++i)
      d(k, i) = st.d(i);
    for (int i = 0; i < 3; ++i) {
      e(k, i) = st.strain(i);
      s(k, i) = st.stress(i);
      p(k, i) = st.plastic(i);
    }
  }
  py::list polygons;  // each block's corners (k, 2) [m], counter-clockwise
  for (const Block& b : m.blocks) {
    Array corners = matrix(b.polygon.vertices.size(), 2);
    auto v = corners.mutable_unchecked<2>();
    for (std::size_t j = 0; j < b.polygon.vertices.size(); ++j) {
      v(j, 0) = b.polygon.vertices[j].x();
      v(j, 1) = b.polygon.vertices[j].y();
    }
    polygons.append(corners);
  }
  py::dict out;
  out["polygons"] = polygons;
  out["centroids"] = centroids;
  out["areas"] = areas;
  out["material"] = material;
  out["unknowns"] = unknowns;
  out["strains"] = strains;
  out["stresses"] = stresses;
  out["plastic_strains"] = plastic;
  return out;
}

py::dict interfaces_of(const Result& r) {
  const Model& m = *r.model;
  const auto n = static_cast<std::size_t>(m.n_interfaces());
  auto blocks = int_matrix(n, 2);
  py::array_t<std::int64_t> material(n);
  Array ends = matrix(n, 4), normals = matrix(n, 2);
  Array points({n, std::size_t{2}, std::size_t{2}}), deltas({n, std::size_t{2}, std::size_t{2}}),
      stresses({n, std::size_t{2}, std::size_t{2}}), plastic({n, std::size_t{2}, std::size_t{2}});
  auto bl = blocks.mutable_unchecked<2>();
  auto mat = material.mutable_unchecked<1>();
  auto en = ends.mutable_unchecked<2>();
  auto no = normals.mutable_unchecked<2>();
  auto pt = points.mutable_unchecked<3>();
  auto de = deltas.mutable_unchecked<3>();
  auto sg = stresses.mutable_unchecked<3>();
  auto pl = plastic.mutable_unchecked<3>();
  for (std::size_t f = 0; f < n; ++f) {
    const Interface& face = m.interfaces[f];
    bl(f, 0) = face.block_i;
    bl(f, 1) = face.block_j;
    mat(f) = face.joint_material;
    en(f, 0) = face.segment.a.x();
    en(f, 1) = face.segment.a.y();
    en(f, 2) = face.segment.b.x();
    en(f, 3) = face.segment.b.y();
    no(f, 0) = face.normal.x();
    no(f, 1) = face.normal.y();
    for (std::size_t k = 0; k < 2; ++k) {
      const InterfacePointState& s = r.fields.interfaces[f][k];
      for (int i = 0; i < 2; ++i) {
        pt(f, k, i) = s.point(i);
        de(f, k, i) = s.delta(i);
        sg(f, k, i) = s.stress(i);
        pl(f, k, i) = s.plastic(i);
      }
    }
  }
  py::dict out;
  out["blocks"] = blocks;
  out["joint_material"] = material;
  out["ends"] = ends;
  out["normals"] = normals;
  out["points"] = points;
  out["deltas"] = deltas;
  out["stresses"] = stresses;
  out["plastic"] = plastic;
  return out;
}

py::dict history_of(const Result& r) {
  const Model& m = *r.model;
  const std::size_t n = r.increments.size();
  py::array_t<std::int64_t> stage(n), increment(n), yielding(n), open(n);
  Array factor(n);
  std::vector<Array> monitors;
  for (std::size_t k = 0; k < m.monitors.size(); ++k)
    monitors.push_back(matrix(n, 2));
  for (std::size_t i = 0; i < n; ++i) {
    const IncrementRecord& rec = r.increments[i].record;
    stage.mutable_at(i) = rec.stage;
    increment.mutable_at(i) = rec.increment;
    factor.mutable_at(i) = rec.stage_factor;
    yielding.mutable_at(i) = rec.yielding_points;
    open.mutable_at(i) = rec.open_points;
    for (std::size_t k = 0; k < monitors.size(); ++k) {
      monitors[k].mutable_at(i, 0) = rec.monitors[k].x();
      monitors[k].mutable_at(i, 1) = rec.monitors[k].y();
    }
  }
  py::dict mon;
  for (std::size_t k = 0; k < monitors.size(); ++k)
    mon[py::str(m.monitors[k].name)] = monitors[k];
  py::dict out;
  out["stage"] = stage;
  out["increment"] = increment;
  out["stage_factor"] = factor;
  out["yielding_points"] = yielding;
  out["open_points"] = open;
  out["monitors"] = mon;
  return out;
}

py::object mechanism_of(const Model& m, const Collapse& c) {
  py::dict out;
  const auto n = c.mechanism.size();
  py::array_t<std::int64_t> point(n), mode(n);
  Array multiplier(n);
  for (std::size_t k = 0; k < n; ++k) {
    point.mutable_at(k) = c.mechanism[k].point;
    mode.mutable_at(k) = c.mechanism[k].mode;
    multiplier.mutable_at(k) = c.mechanism[k].multiplier;
  }
  out["yield_point"] = point;
  out["mode"] = mode;
  out["multiplier"] = multiplier;
  if (c.direction.size() == m.n_dofs()) {
    const MechanismBlocks b = mechanism_blocks(m, c.direction);
    const auto nb = b.blocks.size();
    Array velocity = matrix(nb, 6);
    Array speed(nb);
    py::list motion;
    for (std::size_t k = 0; k < nb; ++k) {
      for (int i = 0; i < 6; ++i)
        velocity.mutable_at(k, i) = b.blocks[k].velocity(i);
      speed.mutable_at(k) = b.blocks[k].speed;
      motion.append(block_motion_name(b.blocks[k].motion));
    }
    out["block_velocities"] = velocity;
    out["block_speeds"] = speed;
    out["block_states"] = motion;
  }
  return py::object(std::move(out));
}

py::object collapse_of(const Result& r) {
  if (!r.plastic || !r.plastic->collapse)
    return py::none();
  const Collapse& c = *r.plastic->collapse;
  py::dict out;
  out["stage"] = c.stage;
  out["stage_name"] = r.model->stages[static_cast<std::size_t>(c.stage)].name;
  out["carried_factor"] = c.carried;
  out["failed_factor"] = c.failed;
  out["unstable_at_first_load"] = c.unstable_at_first_load;
  out["undecided_inside"] = c.undecided_inside;
  out["associated_bound"] = c.associated_bound;
  out["limit_point"] = c.limit_point;
  out["limit_point_plateau_m"] = c.plateau;
  out["limit_point_elastic_m"] = c.elastic;
  out["limit_point_fell"] = c.fell;
  out["mechanism"] = mechanism_of(*r.model, c);
  return py::object(std::move(out));
}

py::object factor_of_safety_of(const Result& r) {
  if (!r.plastic || !r.plastic->factor_of_safety)
    return py::none();
  const FactorOfSafety& f = *r.plastic->factor_of_safety;
  py::dict out;
  out["lower"] = f.lower;
  out["upper"] = f.collapse ? py::object(py::float_(f.collapse->failed)) : py::none();
  out["largest_tried"] = f.largest;
  out["undecided"] = f.undecided;
  Array factors(f.trials.size());
  for (std::size_t k = 0; k < f.trials.size(); ++k)
    factors.mutable_at(k) = f.trials[k].factor;
  out["trials"] = factors;
  out["mechanism"] = f.collapse ? mechanism_of(*r.model, *f.collapse) : py::none();
  return py::object(std::move(out));
}

py::object stopped_of(const Result& r) {
  if (!r.plastic || !r.plastic->stopped)
    return py::none();
  const Stop& s = *r.plastic->stopped;
  py::dict out;
  out["stage"] = s.stage;
  out["carried_factor"] = s.factor;
  out["reason"] = s.reason;
  return py::object(std::move(out));
}

}  // namespace

}  // namespace bimrock::python

PYBIND11_MODULE(_core, m) {
  using namespace bimrock;
  using namespace bimrock::python;
  m.doc() = "bimrock's library for Python: use the package bimrock (docs/python.md)";
  m.attr("__version__") = BIMROCK_VERSION;

  // Python exceptions with the error's parts as attributes (file, line, item, message).
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<ModelError> model_error(m, "ModelError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object exc = py::handle(input_error.ptr())(e.what());
      exc.attr("file") = e.file();
      exc.attr("line") = e.line();
      exc.attr("item") = e.item();
      exc.attr("message") = e.message();
      PyErr_SetObject(input_error.ptr(), exc.ptr());
    } catch (const ModelError& e) {
      py::object exc = py::handle(model_error.ptr())(e.what());
      exc.attr("blocks") = e.blocks();
      PyErr_SetObject(model_error.ptr(), exc.ptr());
    }
  });

  m.def(
      "yaml_to_python", [](const std::string& text) { return to_python(YAML::Load(text)); },
      "a YAML text as Python data, its scalars typed as the case reader types them");
  m.def("install_factor_memory", &install_factor_memory,
        "routes SuiteSparse's allocations through bimrock's recycler of large factor blocks (a "
        "setting of the whole process, as the bimrock command makes it)");

  py::class_<CaseModel>(m, "CaseModel")
      .def_static("file", &CaseModel::file, py::arg("path"))
      .def_static(
          "text",
          [](const std::string& text, const std::string& name, bool lines) {
            return CaseModel::read(text, name, lines, nullptr);
          },
          py::arg("text"), py::arg("name"), py::arg("lines"))
      .def(
          "rebuild",
          [](const CaseModel& self, const std::string& text, const std::string& name) {
            return CaseModel::read(text, name, false, &self);
          },
          py::arg("text"), py::arg("name"))
      .def("check", &CaseModel::check)
      .def("run", &CaseModel::run, py::arg("progress") = py::none())
      .def_property_readonly("title", [](const CaseModel& s) { return s.model->title; })
      .def_property_readonly("block_materials",
                             [](const CaseModel& s) {
                               std::vector<std::string> names;
                               for (const BlockMaterial& b : s.model->block_materials)
                                 names.push_back(b.name);
                               return names;
                             })
      .def_property_readonly("joint_materials",
                             [](const CaseModel& s) {
                               std::vector<std::string> names;
                               for (const JointMaterial& j : s.model->joint_materials)
                                 names.push_back(j.name);
                               return names;
                             })
      .def_property_readonly("monitors",
                             [](const CaseModel& s) {
                               std::vector<std::string> names;
                               for (const Monitor& k : s.model->monitors)
                                 names.push_back(k.name);
                               return names;
                             })
      .def_property_readonly("stages", [](const CaseModel& s) {
        std::vector<std::string> names;
        for (const Stage& k : s.model->stages)
          names.push_back(k.name);
        return names;
      });

  py::class_<Result>(m, "Result")
      .def_property_readonly("analysis",
                             [](const Result& r) { return r.plastic ? "nonlinear" : "elastic"; })
      .def_property_readonly("blocks", &blocks_of)
      .def_property_readonly("interfaces", &interfaces_of)
      .def_property_readonly("history", &history_of)
      .def_property_readonly("collapse", &collapse_of)
      .def_property_readonly("factor_of_safety", &factor_of_safety_of)
      .def_property_readonly("stopped", &stopped_of)
      .def_property_readonly("mean_strain",
                             [](const Result& r) {
                               Array a(3);
                               for (int i = 0; i < 3; ++i)
                                 a.mutable_at(i) = r.fields.mean_strain(i);
                               return a;
                             })
      .def_property_readonly("monitors",
                             [](const Result& r) {
                               py::dict d;
                               for (std::size_t k = 0; k < r.model->monitors.size(); ++k) {
                                 Array a(2);
                                 a.mutable_at(0) = r.fields.monitor_displacements[k].x();
                                 a.mutable_at(1) = r.fields.monitor_displacements[k].y();
                                 d[py::str(r.model->monitors[k].name)] = a;
                               }
                               return d;
                             })
      .def_property_readonly("timings",
                             [](const Result& r) {
                               py::dict d;
                               for (const auto& [phase, seconds] : r.fields.timings.phases)
                                 d[py::str(phase)] = seconds;
                               return d;
                             })
      .def("write", &Result::write, py::arg("folder"));
}
