#include "designer/bench/bench_plan.hpp"

#include <cctype>

#include "designer/design/model_choices.hpp"
#include "models/core/design_record.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kMm = 1e-3;
// CEL cell sizes: the refinement series halves the cell from 20 mm down to 2.5 mm at least, and
// on until three levels resolve the feature (kReferenceCellsAcross) or the cell would be below
// 1 mm.
constexpr double kCoarsestCell = 20 * kMm;
constexpr double kFinestCell = 1 * kMm;
constexpr std::string_view kSeedLaw = "hysteretic_nonlinear2";

// Every alternative of a model key at the reduced rung (the design check).
void add_model_alternatives(BenchQuestion& q, std::string_view key, const std::string& quantity,
                            const std::string& rung) {
  for (const ModelListing& listing : model_options()) {
    if (listing.key != key) continue;
    for (const ModelEntry& e : listing.entries) {
      BenchPoint p;
      p.setting = std::string(key) + "=" + std::string(e.name);
      p.rung = rung;
      p.quantity = quantity;
      p.models = {p.setting};
      p.quick = true;
      q.points.push_back(std::move(p));
    }
  }
}

void add_design_point(BenchQuestion& q, const std::string& quantity, const std::string& rung) {
  BenchPoint p;
  p.setting = "design check";
  p.rung = rung;
  p.quantity = quantity;
  p.quick = true;
  q.points.push_back(std::move(p));
}

// What the CEL points must resolve: `length` [m] of `what` ("the half outlet").
struct Feature {
  double length;
  std::string what;
};

// The CEL refinement series (its levels fine enough for the feature make the reference; its
// coarsest `quick_levels` run in the quick bench) and the remap and flux settings at 10 mm.
void add_cel_points(BenchQuestion& q, const std::string& quantity, std::optional<double> time, const Feature& feature,
                    int quick_levels = 2) {
  int level = 0, resolving = 0;
  for (double h = kCoarsestCell; h >= kFinestCell && (resolving < 3 || h >= 2.5 * kMm); h *= 0.5) {
    BenchPoint p;
    p.setting = "CEL cells " + millimetres_setting(h);
    p.rung = "L2";
    p.quantity = quantity;
    p.solver = Solver::cel;
    p.sets = {"cel.cell_size=" + millimetres_setting(h)};
    p.time = time;
    p.cell_size = h;
    const double across = feature.length / h;
    p.resolution = format_number(across, 2) + " cells across " + feature.what;
    p.role = across >= kReferenceCellsAcross ? ReferenceRole::cel_refinement : ReferenceRole::none;
    resolving += p.role == ReferenceRole::cel_refinement;
    p.quick = level++ < quick_levels;
    q.points.push_back(std::move(p));
  }
  for (const char* remap : {"second"})
    for (const char* flux : {"donor_cell", "limited", "plic"}) {
      BenchPoint p;
      p.setting = std::string("CEL cells 10mm, ") + remap + "-order remap, " + flux + " flux";
      p.rung = "L2";
      p.quantity = quantity;
      p.solver = Solver::cel;
      p.sets = {"cel.cell_size=10mm", std::string("cel.remap_order=") + remap,
                std::string("cel.material_flux=") + flux};
      p.time = time;
      p.cell_size = 10 * kMm;
      p.resolution = format_number(feature.length / (10 * kMm), 2) + " cells across " + feature.what;
      q.points.push_back(std::move(p));
    }
}

// DEM with each normal law at the scene's default resolution (the seed's law: the reference),
// and the seed's law on another slab depth (`slab`, "" for none) and at half the stable step.
void add_dem_points(BenchQuestion& q, const std::string& quantity, const std::string& slab) {
  auto add = [&](std::string setting, std::vector<std::string> sets, ReferenceRole role) {
    BenchPoint p;
    p.setting = std::move(setting);
    p.rung = "L3";
    p.quantity = quantity;
    p.solver = Solver::dem;
    p.sets = std::move(sets);
    p.role = role;
    q.points.push_back(std::move(p));
  };
  const std::string seed_law = "dem.normal_law=" + std::string(kSeedLaw);
  add("DEM hertz", {"dem.normal_law=hertz"}, ReferenceRole::none);
  add("DEM " + std::string(kSeedLaw), {seed_law}, ReferenceRole::dem_reference);
  if (!slab.empty()) add("DEM " + std::string(kSeedLaw) + ", slab " + slab, {seed_law, "dem.slab_depth=" + slab}, ReferenceRole::none);
  add("DEM " + std::string(kSeedLaw) + ", half the stable step", {seed_law, "dem.time_step_safety=0.5"},
      ReferenceRole::none);
}

BenchQuestion hopper_question(std::string id, std::string title, double outlet, bool categorical) {
  BenchQuestion q{std::move(id), std::move(title), "cases/pilot_hopper.toml",
                  {"hopper.outlet_width=" + millimetres_setting(outlet)}, categorical, {}, {}, {}};
  return q;
}

}  // namespace

std::string millimetres_setting(double metres) {
  std::string s = std::to_string(metres / kMm);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s + "mm";
}

BenchQuestion verification_run_question(std::string id, std::string case_file,
                                        std::vector<std::string> sets, std::string set) {
  BenchQuestion q;
  q.id = std::move(id);
  q.case_file = std::move(case_file);
  q.sets = std::move(sets);
  q.sets.push_back(std::move(set));
  return q;
}

BenchPoint dem_verification_point(std::string setting, std::string quantity) {
  BenchPoint p;
  p.setting = std::move(setting);
  p.rung = "L3";
  p.quantity = std::move(quantity);
  p.solver = Solver::dem;
  return p;
}

std::string file_name_friendly(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  return text;
}

std::string point_id(const BenchPoint& point) { return file_name_friendly(point.rung + "_" + point.setting); }

BenchQuestion chute_question(std::string id, std::string title, std::string case_file,
                             std::vector<std::string> sets, double deposit, int quick_levels) {
  BenchQuestion q{
      std::move(id), std::move(title), std::move(case_file), std::move(sets), false, {}, {}, {}};
  add_model_alternatives(q, "chute.stopping_thickness", "stopping_thickness", "L0");
  add_model_alternatives(q, "chute.deposit", "deposit_thickness_mid_ramp", "L1");
  add_cel_points(q, "deposit_thickness_mid_ramp", std::nullopt, {deposit, "the deposit"},
                 quick_levels);
  for (auto& p : q.points)
    if (p.solver == Solver::cel) p.rest_key = "at_rest";
  add_dem_points(q, "deposit_thickness_mid_ramp", "24mm");
  // The seed's whole plane is a point, not the reference: at the seed's resolution it holds about
  // 180 000 spheres (100 h an angle on one thread). h_stop's reference on the particle rung is
  // the bisection of periodic stopping layers to one sphere (about 1 100 spheres for 30 mm).
  for (auto& p : q.points)
    if (p.role == ReferenceRole::dem_reference) p.role = ReferenceRole::none;
  BenchPoint layers;
  layers.setting = "DEM " + std::string(kSeedLaw) + ", stopping layers bisected to one sphere";
  layers.rung = "L3";
  layers.quantity = "stopping_thickness";
  layers.verify = "dem";
  layers.role = ReferenceRole::dem_reference;
  q.points.push_back(std::move(layers));
  return q;
}

BenchQuestion drum_question(const std::string& rpm, bool regime) {
  BenchQuestion q{std::string("drum_") + (regime ? "regime_" : "angle_") + rpm + "rpm",
                  std::string("Rotating drum at ") + rpm +
                      " rpm: " + (regime ? "bed regime" : "dynamic angle of repose"),
                  "cases/rotating_drum_20rpm.toml",
                  {"drum.speed=" + rpm + "rpm"},
                  regime,
                  {},
                  {},
                  {}};
  const std::string quantity = regime ? "regime" : "dynamic_angle_of_repose";
  add_design_point(q, quantity, "L0");
  add_cel_points(q, quantity, std::nullopt, {72.5 * kMm, "the drum's radius"});
  add_dem_points(q, quantity, "18mm");  // the default is the seed's whole 3D drum
  if (!regime)
    for (auto& p : q.points)
      if (p.solver) p.interval_key = interval_key(quantity);
  return q;
}

std::vector<BenchQuestion> seed_bench_questions() {
  std::vector<BenchQuestion> questions;
  constexpr double kHopperTime = 1.0;  // [s] after the opening: the rate's batch means settle

  // The pilot hopper's questions: each with the model key whose alternatives answer it.
  struct HopperQuestion {
    const char* id;
    const char* title;
    double outlet;
    bool categorical;
    const char* model_key;
    const char* quantity;
  };
  for (const HopperQuestion& h : {
           HopperQuestion{"hopper_discharge_rate_60mm", "Pilot hopper: mass discharge rate at W = 60 mm", 60 * kMm,
                          false, "hopper.discharge", "mass_flow_rate"},
           HopperQuestion{"hopper_arching_20mm", "Pilot hopper: does it arch at W = 20 mm?", 20 * kMm, true,
                          "hopper.critical_outlet", "arching"},
           HopperQuestion{"hopper_flow_pattern_60mm", "Pilot hopper: mass or funnel flow at 30 deg", 60 * kMm, true,
                          "hopper.flow_factor", "flow_pattern"}}) {
    BenchQuestion q = hopper_question(h.id, h.title, h.outlet, h.categorical);
    add_model_alternatives(q, h.model_key, h.quantity, "L0");
    add_cel_points(q, h.quantity, kHopperTime, {0.5 * h.outlet, "the half outlet"});
    if (std::string(h.quantity) == "arching")  // B_c against the outlet: above it, the outlet arches
      for (auto& p : q.points)
        if (p.rung == "L0") {
          p.quantity = "critical_outlet_width";
          p.label_rule = BenchPoint::LabelRule{h.outlet, "arched", "flowing"};
        }
    add_dem_points(q, h.quantity, "12mm");  // four diameters against the default one layer
    if (!h.categorical)  // the rate's band is the 95 % interval of its batch means
      for (auto& p : q.points)
        if (p.solver) p.interval_key = p.quantity;
    questions.push_back(std::move(q));
  }

  {  // B_c: the continuum cannot arch (its law has no cohesion), so only the particle rung
     // measures it: the seed's law with K_nc's pull, bisected over the reduced band to 2.5 mm,
     // on half the seed's fill (B_c is set at the outlet; 0.35 m halves the spheres).
    BenchQuestion q =
        hopper_question("hopper_critical_outlet_width",
                        "Pilot hopper: critical outlet width B_c at 30 deg", 45 * kMm, false);
    add_model_alternatives(q, "hopper.critical_outlet", "critical_outlet_width", "L0");
    BenchPoint p;
    p.setting = "DEM " + std::string(kSeedLaw) + " + k_nc, 0.35 m fill, bisection to 2.5 mm";
    p.rung = "L3";
    p.quantity = "critical_outlet_width";
    p.sets = {"dem.cohesion=k_nc", "hopper.fill_height=0.35m"};
    p.verify = "dem";
    p.width_tolerance = "2.5mm";
    p.role = ReferenceRole::dem_reference;
    q.points.push_back(std::move(p));
    questions.push_back(std::move(q));
  }

  for (const char* angle : {"29_5", "37"}) {
    const bool steep = angle == std::string("37");
    // The flow comes to rest after ~9 s at 29.5 deg and ~30 s at 37 deg (L1): a CEL run at
    // 20 mm takes minutes at 29.5 deg, so the quick bench has that one level only.
    // The deposit the cells must resolve: about 45 mm at 29.5 deg, 3.5 mm at 37 deg (L0).
    questions.push_back(chute_question(std::string("chute_stopping_thickness_") + angle,
                                       std::string("Inclined plane at ") + (steep ? "37" : "29.5") +
                                           " deg: deposit thickness mid-ramp",
                                       std::string("cases/inclined_plane_") + angle + ".toml", {},
                                       steep ? 3.5 * kMm : 45 * kMm, steep ? 0 : 1));
  }

  for (const char* rpm : {"10", "20", "50"})
    for (bool regime : {false, true}) questions.push_back(drum_question(rpm, regime));
  return questions;
}

}  // namespace feedflow
