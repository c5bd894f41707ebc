#include <bimrock/io/run_summary.hpp>

#include <map>

#include <bimrock/analysis/mechanism_blocks.hpp>
#include <bimrock/analysis/mechanism_joints.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/io/history_writer.hpp>
#include <bimrock/io/text_file.hpp>

namespace bimrock {

namespace {

using nlohmann::json;

json model_json(const Model& model) {
  int supports = 0;
  for (const Interface& f : model.interfaces)
    supports += f.is_support() ? 1 : 0;
  return {{"blocks", model.n_blocks()},
          {"interfaces", model.n_interfaces() - supports},
          {"support_interfaces", supports},
          {"unknowns", model.n_dofs()},
          {"area_m2", total_area(model)},
          {"length_tolerance_m", model.tolerance},
          {"plane", model.settings.plane == PlaneMode::strain ? "strain" : "stress"},
          {"thickness_m", model.settings.thickness}};
}

json timings_json(const Timings& t) {
  json j = json::object();
  for (const auto& [phase, seconds] : t.phases)
    j[phase] = seconds;
  j["total"] = t.total();
  return j;
}

json mechanism_json(const Model& model, const std::vector<YieldPoint>& points, const Collapse& c,
                    const std::vector<MechanismJoint>& joints) {
  static constexpr const char* kJointModes[] = {"slip+", "slip-", "opening"};
  std::map<int, JointMotion> net;
  for (const MechanismJoint& j : joints)
    net[j.point] = j.motion;
  json list = json::array();
  for (const MechanismEntry& e : c.mechanism) {
    const YieldPoint& p = points[static_cast<std::size_t>(e.point)];
    json item = {{"multiplier", e.multiplier}, {"x_m", p.position.x()}, {"y_m", p.position.y()}};
    if (p.is_interface()) {
      item["interface"] = p.owner;
      item["block_i"] = p.block_i;
      item["block_j"] = p.block_j;
      item["mode"] = e.mode >= 0 && e.mode < 3 ? kJointModes[e.mode] : "?";
      const auto it = net.find(e.point);
      if (it != net.end())
        item["net_mode"] = joint_motion_name(it->second);
    } else if (p.is_bolt()) {
      static constexpr const char* kBoltModes[] = {"tension", "shear+", "shear-"};
      item["bolt_spring"] = p.owner;
      item["bolt"] = bolt_of(model, p).name;
      item["mode"] = e.mode >= 0 && e.mode < 3 ? kBoltModes[e.mode] : "?";
    } else {
      item["block"] = p.owner;
      item["mode"] = "plane " + std::to_string(e.mode);
    }
    list.push_back(std::move(item));
  }
  return list;
}

json mechanism_blocks_json(const MechanismBlocks& m) {
  json moves = json::array();
  json rotates = json::array();
  json stands = json::array();
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    const BlockMotion motion = m.blocks[b].motion;
    (motion == BlockMotion::moves     ? moves
     : motion == BlockMotion::rotates ? rotates
                                      : stands)
        .push_back(b);
  }
  return {{"moves", moves}, {"rotates", rotates}, {"stands", stands}};
}

json mechanism_joints_json(const std::vector<YieldPoint>& points,
                           const std::vector<MechanismJoint>& joints) {
  json list = json::array();
  for (const MechanismJoint& j : joints) {
    const YieldPoint& p = points[static_cast<std::size_t>(j.point)];
    list.push_back({{"interface", p.owner},
                    {"block_i", p.block_i},
                    {"block_j", p.block_j},
                    {"x_m", p.position.x()},
                    {"y_m", p.position.y()},
                    {"delta_n", j.delta(0)},
                    {"delta_s", j.delta(1)},
                    {"net_mode", joint_motion_name(j.motion)}});
  }
  return list;
}

// The factor of safety: its bracket, every F carried, and the mechanism at the smallest F proven
// to fail.
json factor_of_safety_json(const Model& model, const std::vector<YieldPoint>& points,
                           const FactorOfSafety& f) {
  json trials = json::array();
  for (const FactorTrial& t : f.trials) {
    json monitors = json::object();
    for (std::size_t m = 0; m < model.monitors.size() && m < t.monitors.size(); ++m)
      monitors[model.monitors[m].name] = {t.monitors[m].x(), t.monitors[m].y()};
    trials.push_back({{"factor", t.factor},
                      {"largest_flow_m", t.largest_flow},
                      {"monitor_displacements_m", monitors}});
  }
  json out = {{"after_stage", model.stages[static_cast<std::size_t>(f.stage)].name},
              {"lower", f.lower},
              {"upper", f.collapse ? json(f.collapse->failed) : json()},
              {"largest_tried", f.largest},
              {"undecided", f.undecided},
              {"trials", trials}};
  if (f.collapse) {
    const MechanismBlocks blocks = mechanism_blocks(model, f.collapse->direction);
    const std::vector<MechanismJoint> joints =
        mechanism_joints(model, points, *f.collapse, blocks.scale);
    out["mechanism"] = mechanism_json(model, points, *f.collapse, joints);
    out["mechanism_joints"] = mechanism_joints_json(points, joints);
    if (f.collapse->direction.size() == model.n_dofs())
      out["mechanism_blocks"] = mechanism_blocks_json(blocks);
  }
  return out;
}

}  // namespace

json run_summary(const Model& model, const ElasticSolution& fields, const PlasticResult* plastic,
                 const std::vector<std::string>& files) {
  json j;
  j["program"] = "bimrock";
  j["bimrock_version"] = BIMROCK_VERSION;
  j["case"] = model.source_file;
  j["title"] = model.title;
  j["units"] = "SI: m, N, Pa; tension positive";
  j["analysis"] = plastic ? "nonlinear" : "elastic";
  j["model"] = model_json(model);
  j["mean_strain"] = {{"eps_x", fields.mean_strain(0)},
                      {"eps_y", fields.mean_strain(1)},
                      {"gamma_xy", fields.mean_strain(2)}};
  json monitors = json::array();
  for (std::size_t k = 0; k < model.monitors.size(); ++k) {
    const Vec2& p = model.monitors[k].point;
    const Vec2& u = fields.monitor_displacements[k];
    monitors.push_back({{"name", model.monitors[k].name},
                        {"x_m", p.x()},
                        {"y_m", p.y()},
                        {"ux_m", u.x()},
                        {"uy_m", u.y()}});
  }
  j["monitors"] = monitors;
  if (plastic) {
    json stages = json::array();
    for (std::size_t s = 0; s < model.stages.size(); ++s) {
      const Stage& st = model.stages[s];
      int carried = 0;
      double factor = 0.0;
      for (const IncrementRecord& r : plastic->history) {
        if (r.stage != static_cast<int>(s))
          continue;
        ++carried;
        factor = r.stage_factor;
      }
      json item = {{"name", st.name},
                   {"increments", st.increments},
                   {"carried_steps", carried},
                   {"final_factor", factor},
                   {"point_load_N", point_load_resultant(st)}};
      if (st.control)
        item["control_displacement_m"] = st.control->displacement;
      if (!st.excavated.empty()) {
        item["excavated_blocks"] = st.excavated;
        item["release"] = st.release;
      }
      stages.push_back(std::move(item));
    }
    j["stages"] = stages;
    if (plastic->collapse) {
      const Collapse& c = *plastic->collapse;
      const Stage& st = model.stages[static_cast<std::size_t>(c.stage)];
      const double load = point_load_resultant(st);
      const MechanismBlocks blocks = mechanism_blocks(model, c.direction);
      const std::vector<MechanismJoint> joints =
          mechanism_joints(model, plastic->points, c, blocks.scale);
      j["collapse"] = {{"stage", st.name},
                       {"carried_factor", c.carried},
                       {"failed_factor", c.failed},
                       {"carried_point_load_N", c.carried * load},
                       {"failed_point_load_N", c.failed * load},
                       {"unstable_at_first_load", c.unstable_at_first_load},
                       {"undecided_inside", c.undecided_inside},
                       {"associated_bound", c.associated_bound},
                       {"limit_point", c.limit_point},
                       {"limit_point_plateau_m", c.plateau},
                       {"limit_point_elastic_m", c.elastic},
                       {"limit_point_fell", c.fell},
                       {"mechanism", mechanism_json(model, plastic->points, c, joints)},
                       {"mechanism_joints", mechanism_joints_json(plastic->points, joints)}};
      if (c.direction.size() == model.n_dofs())
        j["collapse"]["mechanism_blocks"] = mechanism_blocks_json(blocks);
    } else {
      j["collapse"] = nullptr;
    }
    // K once (and again after each stage that excavates), again in another order for each zone
    // or region it was condensed onto; the reduced tangents of the LCPs besides. The strengths
    // of a factor of safety change none.
    j["factorizations"] = {{"stiffness", plastic->stiffness_factorizations +
                                             plastic->condensations + plastic->regions},
                           {"tangents", plastic->tangent_factorizations}};
    if (!model.bolts.empty()) {
      int standing = 0;
      int yielded = 0;
      double most_used = 0.0;
      for (const SpringState& r : fields.springs) {
        standing += r.standing ? 1 : 0;
        yielded += r.yielded ? 1 : 0;
        if (r.standing)
          most_used = std::max(most_used, r.capacity_used);
      }
      j["bolts"] = {{"bolts", model.bolts.size()},
                    {"springs", model.bolt_springs.size()},
                    {"standing_springs", standing},
                    {"yielded_springs", yielded},
                    {"largest_capacity_used", most_used}};
    }
    if (plastic->initial_stress)
      j["initial_stress"] = {{"residual_N", plastic->initial_stress->residual},
                             {"relative_residual", plastic->initial_stress->relative_residual},
                             {"violated_points", plastic->initial_stress->violated_points}};
    if (plastic->factor_of_safety)
      j["factor_of_safety"] =
          factor_of_safety_json(model, plastic->points, *plastic->factor_of_safety);
    if (plastic->stopped) {
      const Stop& st = *plastic->stopped;
      j["stopped"] = {{"stage", model.stages[static_cast<std::size_t>(st.stage)].name},
                      {"carried_factor", st.factor},
                      {"reason", st.reason}};
    } else {
      j["stopped"] = nullptr;
    }
  }
  j["timings_s"] = timings_json(plastic ? plastic->timings : fields.timings);
  j["files"] = files;
  return j;
}

void write_json(const json& json, const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  out << json.dump(2) << '\n';
  check_written(out, file);
}

}  // namespace bimrock
