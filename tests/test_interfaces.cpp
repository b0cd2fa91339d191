// Bonded interfaces between two materials (doc/physics.md "Interface joints", doc/deck.md
// "[interfaces.A_B]"): the deck's keys and errors, which edges carry joints, the moisture
// nodes, a bonded cracking run on 1 and 2 threads, and the law between two deformable materials
// (verification/interface_debonding checks it against a rigid base).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "tests/test_support.h"
#include "ycore/driver/coupling.h"
#include "ycore/driver/setup.h"
#include "ycore/input/input_error.h"
#include "ycore/solid/energies.h"
#include "ycore/state/build_state.h"
#include "ycrack/crack_statistics.h"
#include "ycrack/interface_debonding.h"

using namespace ydry;
using namespace ydry_test;

namespace {

// Soil over a base on tests/data/two_materials.msh (the curve "interface" between them), both
// deformable and wet, with mechanics; the interface as the overrides make it.
Deck soil_on_base(TempDir& dir, const std::vector<std::string>& sets = {}) {
  write_text(dir.file("deck.toml"), R"(
[run]
name = "soil_on_base"
end_time = 1.0
output_interval = 1.0
[mesh]
file = ")" YDRY_SOURCE_DIR R"(/tests/data/two_materials.msh"
[materials.soil]
density = 1300.0
young = 1.0e6
poisson = 0.3
tensile_strength = 1.0e4
cohesion = 1.0e4
friction_angle = 30.0
gf_I = 10.0
gf_II = 10.0
shrinkage_coefficient = 0.1
moisture_conductivity = 2.0e-6
initial_moisture = 0.3
[materials.base]
density = 2700.0
young = 4.0e6
poisson = 0.3
breakable = false
shrinkage_coefficient = 0.0
moisture_conductivity = 0.0
initial_moisture = 0.1
)");
  return load_deck(dir.file("deck.toml"), sets);
}

const std::vector<std::string> kBonded = {
    "interfaces.base_soil={bonded=true, tensile_strength=2.0e3, cohesion=3.0e3, friction_angle=25.0, "
    "gf_I=1.0, gf_II=2.0}"};

// The mesh edges shared by two triangles, as sorted vertex pairs, by the sorted pair of their
// materials' names.
std::map<std::pair<std::string, std::string>, std::set<std::pair<index_t, index_t>>> shared_edges(const MeshInput& mesh) {
  std::map<std::pair<index_t, index_t>, std::vector<index_t>> sides;
  for (index_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e)
      sides[std::minmax(mesh.tri[3 * t + e], mesh.tri[3 * t + (e + 1) % 3])].push_back(t);
  std::map<std::pair<std::string, std::string>, std::set<std::pair<index_t, index_t>>> edges;
  for (const auto& [edge, triangles] : sides)
    if (triangles.size() == 2)
      edges[std::minmax(mesh.tri_material[triangles[0]], mesh.tri_material[triangles[1]])].insert(edge);
  return edges;
}

std::pair<index_t, index_t> joint_edge(const State& s, std::size_t j) {
  return std::minmax(s.nodes.vertex[s.joints.node[4 * j]], s.nodes.vertex[s.joints.node[4 * j + 1]]);
}

// The rectangle of the two tests below, base (E 16 MPa) under soil (E 4 MPa), both elastic with
// nu = 0 and unbreakable, without gravity, bonded by kBonded's interface and loaded as `sets`
// say, run one coupling second at a time to its end. Returns the peak of the top's reaction
// along `axis` (0 x, 1 y) and, at that peak, the mean move along it of the base's corners on
// the interface (y = 0.5 m), with the deck and the state at the end.
struct RectangleRun {
  Deck deck;
  State state;
  double peak_reaction = 0, base_top_move = 0;
};
RectangleRun run_bonded_rectangle(TempDir& dir, const std::vector<std::string>& sets, int axis) {
  std::vector<std::string> all = {kBonded[0], "run.gravity=[0.0, 0.0]", "solver.max_coupling_step=1.0",
                                  "materials.soil.young=4.0e6", "materials.soil.poisson=0.0",
                                  "materials.soil.breakable=false", "materials.base.young=1.6e7",
                                  "materials.base.poisson=0.0"};
  all.insert(all.end(), sets.begin(), sets.end());
  RectangleRun run{soil_on_base(dir, all), {}};
  run.state = setup_state(run.deck);
  State& s = run.state;
  const auto top = std::find_if(s.mechanics_boundaries.begin(), s.mechanics_boundaries.end(),
                                [](const MechanicsBoundary& b) { return b.name == "top"; });
  REQUIRE(top != s.mechanics_boundaries.end());
  const std::uint16_t base = material_id(s, "base");
  const auto base_top_move = [&] {
    double sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < s.nodes.size(); ++i)
      if (s.triangles.material[triangle_of(index_t(i))] == base && std::fabs(s.nodes.y0[i] - 0.5) < 1e-9)
        sum += axis == 0 ? s.nodes.x[i] - s.nodes.x0[i] : s.nodes.y[i] - s.nodes.y0[i], ++count;
    return sum / count;
  };
  double step_limit = coupling_step_limit(s, run.deck);
  for (double t = 1.0; t <= run.deck.end_time_s; t += 1.0) {
    step_limit = advance_to(s, run.deck, t, step_limit);
    const double reaction = axis == 0 ? top->reaction_x : top->reaction_y;
    if (reaction > run.peak_reaction) run.peak_reaction = reaction, run.base_top_move = base_top_move();
  }
  return run;
}

// What a run of the rectangle must show when its whole interface opens or slides as one
// cohesive crack of area A = 2 m x 1 m: no relaxation capped, the top's reaction peaking at
// strength x A, the base's top moved at that peak by (peak / A) / modulus x 0.5 m (the base's
// E in tension, G in shear), all 2 m debonded, and the broken joints' work gf x A; each
// within 2 %.
void check_one_cohesive_crack(const RectangleRun& run, double strength, double gf, double modulus) {
  const double area = 2.0 * run.deck.thickness_m;
  CHECK(run.state.mechanics.capped_relaxations == 0);
  CHECK(run.peak_reaction / area == Approx(strength).epsilon(0.02));
  CHECK(run.base_top_move == Approx(run.peak_reaction / area / modulus * 0.5).epsilon(0.02));
  const std::vector<double> debonded = interface_debonded_lengths(run.state);
  REQUIRE(debonded.size() == 1);
  CHECK(debonded[0] == Approx(2.0).epsilon(1e-9));  // all of it
  CHECK(energies(run.state).fracture_J / area == Approx(gf).epsilon(0.02));
}

}  // namespace

TEST_CASE("an [interfaces.A_B] table is read in either order, with its defaults", "[interfaces]") {
  TempDir dir;
  const Deck plain = soil_on_base(dir);
  CHECK(plain.interfaces.empty());
  CHECK(plain.resolved.get("interfaces") == nullptr);  // a deck without them resolves as before

  const Deck deck = soil_on_base(dir, kBonded);
  REQUIRE(deck.interfaces.size() == 1);
  const InterfaceDeck& f = deck.interfaces[0];
  CHECK(f.name == "base_soil");
  CHECK(f.materials == std::make_pair(std::string("base"), std::string("soil")));
  CHECK(f.bonded);
  CHECK(f.tensile_strength == 2.0e3);
  CHECK(f.cohesion == 3.0e3);
  CHECK(f.gf_I == 1.0);
  CHECK(f.gf_II == 2.0);
  CHECK(f.joint_penalty == deck.joint_penalty);  // solver.joint_penalty, as a material's joints
  // Its friction angle is the pair's contact friction once debonded.
  CHECK(deck.friction_deg.at({"base", "soil"}) == 25.0);

  const Deck contact_only = soil_on_base(dir, {"interfaces.soil_base.bonded=false"});
  REQUIRE(contact_only.interfaces.size() == 1);
  CHECK_FALSE(contact_only.interfaces[0].bonded);
  CHECK(contact_only.friction_deg.empty());
}

TEST_CASE("a wrong [interfaces] table is an InputError that names it", "[interfaces]") {
  TempDir dir;
  const auto error = [&](const std::vector<std::string>& sets) {
    try {
      soil_on_base(dir, sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error({"interfaces.soil_rock.bonded=true"}),
             Catch::Contains("interfaces.soil_rock") && Catch::Contains("two materials of the deck"));
  CHECK_THAT(error({"interfaces.soilbase.bonded=false"}), Catch::Contains("interfaces.soilbase"));
  CHECK_THAT(error({"interfaces.soil_soil.bonded=false"}), Catch::Contains("two different materials"));
  CHECK_THAT(error({"interfaces.soil_base.glue=1.0"}), Catch::Contains("interfaces.soil_base.glue: unknown key"));
  CHECK_THAT(error({"interfaces.soil_base={bonded=true, cohesion=3.0e3, friction_angle=25.0, gf_I=1.0, gf_II=2.0}"}),
             Catch::Contains("interfaces.soil_base.tensile_strength: required key is missing"));
  CHECK_THAT(error({"interfaces.soil_base={bonded=false, cohesion=3.0e3}"}),
             Catch::Contains("interfaces.soil_base.cohesion: only a bonded interface"));
  CHECK_THAT(error({"interfaces.soil_base.bonded=false", "interfaces.base_soil.bonded=false"}),
             Catch::Contains("the same pair of materials"));
  CHECK_THAT(error({kBonded[0], "contact.friction={soil_base=20.0}"}), Catch::Contains("contact.friction"));
  CHECK_THAT(error({"interfaces.base_soil={bonded=true, tensile_strength=-1.0, cohesion=3.0e3, friction_angle=25.0, "
                    "gf_I=1.0, gf_II=2.0}"}),
             Catch::Contains("interfaces.base_soil.tensile_strength: value -1 out of range"));
  CHECK_THAT(error({"interfaces=3"}), Catch::Contains("interfaces: expected a table"));
}

TEST_CASE("without a bonded interface the joints are the edges inside one material; with one, also its edges",
          "[interfaces]") {
  TempDir dir;
  const Deck plain = soil_on_base(dir), bonded = soil_on_base(dir, kBonded),
             unbonded = soil_on_base(dir, {"interfaces.soil_base.bonded=false"});
  const MeshInput mesh = load_mesh(plain);
  const auto edges = shared_edges(mesh);
  const std::size_t inside = edges.at({"base", "base"}).size() + edges.at({"soil", "soil"}).size();
  const std::set<std::pair<index_t, index_t>>& interface = edges.at({"base", "soil"});
  REQUIRE(interface.size() >= 5);  // the 2 m curve "interface" at h = 0.4

  const State s0 = build_state(mesh, plain), s1 = build_state(mesh, bonded), s2 = build_state(mesh, unbonded);
  CHECK(s0.joints.size() == inside);
  CHECK(s2.joints.node == s0.joints.node);  // bonded = false: contact only, the joints of no interface
  CHECK(s2.joints.law == s0.joints.law);
  REQUIRE(s1.joints.size() == inside + interface.size());
  CHECK(s1.interface_names == std::vector<std::string>{"base_soil"});
  std::set<std::pair<index_t, index_t>> bonded_edges;
  for (std::size_t j = 0; j < s1.joints.size(); ++j) {
    const std::uint16_t m0 = s1.triangles.material[triangle_of(s1.joints.node[4 * j])];
    const std::uint16_t m1 = s1.triangles.material[triangle_of(s1.joints.node[4 * j + 2])];
    CHECK(is_interface_joint(s1, j) == (m0 != m1));
    if (!is_interface_joint(s1, j)) {
      CHECK(s1.joints.law[j] == m0);
      continue;
    }
    CHECK(s1.joints.law[j] == s1.material_names.size());  // the first interface's properties
    bonded_edges.insert(joint_edge(s1, j));
  }
  CHECK(bonded_edges == interface);
  // The joints inside the materials are those of the deck without the interface, in order.
  std::vector<index_t> inside_nodes;
  for (std::size_t j = 0; j < s1.joints.size(); ++j)
    if (!is_interface_joint(s1, j)) inside_nodes.insert(inside_nodes.end(), &s1.joints.node[4 * j], &s1.joints.node[4 * j + 4]);
  CHECK(inside_nodes == s0.joints.node);
}

TEST_CASE("a bonded interface's joints take its properties; they tie its corners for the solid, not for the water",
          "[interfaces]") {
  TempDir dir;
  const State plain = prepare_state(soil_on_base(dir));
  const State bonded = prepare_state(soil_on_base(dir, kBonded));
  const std::size_t nm = bonded.material_names.size();
  REQUIRE(bonded.materials.size() == nm + 1);
  const MaterialModel& f = bonded.materials[nm];
  CHECK(f.mechanical);
  CHECK(f.tensile_strength == 2.0e3);
  CHECK(f.cohesion == 3.0e3);
  CHECK(f.tan_friction == Approx(std::tan(25.0 * M_PI / 180.0)).epsilon(1e-15));
  CHECK(f.penalty == 1000.0 * 1.0e6);  // solver.joint_penalty x the softer E (the soil's)
  // Every corner of an interface joint is tied to its partner across the interface ...
  for (std::size_t j = 0; j < bonded.joints.size(); ++j) {
    if (!is_interface_joint(bonded, j)) continue;
    const index_t* n = &bonded.joints.node[4 * j];
    CHECK(bonded.nodes.tie_group[n[0]] == bonded.nodes.tie_group[n[3]]);
    CHECK(bonded.nodes.tie_group[n[1]] == bonded.nodes.tie_group[n[2]]);
  }
  // ... but the moisture nodes are those of the unbonded materials: no water crosses, even
  // into a base whose conductivity is 0.
  CHECK(bonded.nodes.mnode == plain.nodes.mnode);
  CHECK(bonded.moisture.w == plain.moisture.w);
  CHECK(bonded.moisture.dry_mass == plain.moisture.dry_mass);
}

TEST_CASE("a layer bonded to its rigid base debonds bitwise the same on 1 and 2 threads", "[interfaces][threads]") {
  std::vector<std::string> sets = kCrackingLayer;
  sets.insert(sets.end(), {"contact.friction={soil_soil=20.0}",
                           "interfaces.soil_base={bonded=true, tensile_strength=300.0, cohesion=300.0, "
                           "friction_angle=20.0, gf_I=1.0e-4, gf_II=1.0e-4}"});
  const Deck deck = load_deck(kPeronDeck, sets);
  Snapshot state[2];
  std::vector<double> debonded[2];
  State last;
  on_1_and_2_threads([&](int threads) {
    State s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    state[threads - 1] = state_snapshot(s);
    debonded[threads - 1] = interface_debonded_lengths(s);
    last = std::move(s);
  });
  // It means something: the interface came apart somewhere, and its base stayed where it was.
  REQUIRE(debonded[0].size() == 1);
  CHECK(debonded[0][0] > 0.0);
  CHECK(same_bits(debonded[0], debonded[1]));
  const std::uint16_t base = material_id(last, "base");
  for (std::size_t i = 0; i < last.nodes.size(); ++i)
    if (last.triangles.material[triangle_of(index_t(i))] == base) {
      CHECK(last.nodes.x[i] == last.nodes.x0[i]);
      CHECK(last.nodes.y[i] == last.nodes.y0[i]);
    }
  for (const auto& [name, values] : state[0]) {
    INFO(name);
    CHECK(same_bits(values, state[1][name]));
  }
}

TEST_CASE("a crack that reaches a debonded interface penetrates; the debonding itself is no crack", "[interfaces]") {
  TempDir dir;
  State s = prepare_state(soil_on_base(dir, kBonded));
  const std::uint16_t base = material_id(s, "base");
  const double base_bottom = *std::min_element(s.nodes.y0.begin(), s.nodes.y0.end());
  // A joint of the base (0 <= y <= 0.5) from the interface y = 0.5 down into the base, short of
  // its bottom; and an interface joint at its top end.
  std::size_t crack = s.joints.size(), interface = s.joints.size();
  for (std::size_t j = 0; j < s.joints.size() && interface == s.joints.size(); ++j) {
    const index_t* n = &s.joints.node[4 * j];
    if (s.joints.law[j] != base || s.nodes.y0[n[0]] <= base_bottom + 1e-9 || s.nodes.y0[n[1]] <= base_bottom + 1e-9)
      continue;
    const index_t top = s.nodes.y0[n[0]] > s.nodes.y0[n[1]] ? n[0] : n[1];
    if (std::fabs(s.nodes.y0[top] - 0.5) > 1e-9) continue;
    for (std::size_t k = 0; k < s.joints.size(); ++k) {
      const index_t* m = &s.joints.node[4 * k];
      if (is_interface_joint(s, k) && (s.nodes.vertex[m[0]] == s.nodes.vertex[top] || s.nodes.vertex[m[1]] == s.nodes.vertex[top])) {
        crack = j, interface = k;
        break;
      }
    }
  }
  REQUIRE(interface < s.joints.size());
  s.joints.broken[crack] = 1;
  std::vector<Crack> cracks = find_all_cracks(s);
  REQUIRE(cracks.size() == 1);
  CHECK_FALSE(cracks[0].penetrating);  // short of the base's bottom, at a bonded interface
  s.joints.broken[interface] = 1;
  cracks = find_all_cracks(s);
  REQUIRE(cracks.size() == 1);  // the broken interface joint is no crack of its own
  CHECK(cracks[0].joints == std::vector<index_t>{index_t(crack)});
  CHECK(cracks[0].penetrating);
  CHECK(interface_debonded_lengths(s) == std::vector<double>{s.joints.length0[interface]});
}

TEST_CASE("a debonded interface's faces exchange no water with the air; a crack's faces do", "[interfaces]") {
  TempDir dir;
  const Deck deck = soil_on_base(dir, {kBonded[0], "moisture.cracks={exchange_coefficient=1.0e-5, air_moisture=0.02}"});
  State s = prepare_state(deck);
  const std::uint16_t soil = material_id(s, "soil");
  std::size_t crack = s.joints.size(), debonded = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    if (is_interface_joint(s, j)) {
      s.joints.broken[j] = 1, ++debonded;
    } else if (crack == s.joints.size() && s.joints.law[j] == soil) {
      crack = j;
    }
  }
  REQUIRE(debonded > 0);
  REQUIRE(crack < s.joints.size());
  s.joints.broken[crack] = 1;
  split_across_broken_joints(s, deck);
  // The deck has no moisture boundary: the exchange terms are the crack's two faces, half its
  // length at each of their four corners, and none on the whole debonded interface.
  const double half_area = 0.5 * s.joints.length0[crack] * deck.thickness_m;
  std::size_t exchanges = 0;
  for (std::size_t k = 0; k < s.moisture.term_kind.size(); ++k)
    if (s.moisture.term_kind[k] == MoistureTermKind::exchange) {
      ++exchanges;
      CHECK(s.moisture.term_area[k] == Approx(half_area).epsilon(1e-12));
    }
  CHECK(exchanges == 4);
}

TEST_CASE("log.txt names each bonded interface with its joints and properties", "[interfaces][output]") {
  TempDir dir;
  const State s = prepare_state(soil_on_base(dir, kBonded));  // writes dir's deck.toml
  REQUIRE(s.interface_names.size() == 1);
  std::size_t joints = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j) joints += is_interface_joint(s, j);
  REQUIRE(joints > 0);
  // Without gravity: nothing supports the two bodies, which under their weight would fall.
  const CommandResult r = run_ydry(dir.file("deck.toml") + " -o " + dir.file("out") + " --quiet --set '" + kBonded[0] +
                                   "' --set run.gravity=[0.0,0.0]");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string log = read_text(dir.file("out/log.txt"));
  CHECK(log.find("interfaces." + s.interface_names[0] + ": " + std::to_string(joints) +
                 " bonded joints, tensile strength 2000 Pa, cohesion 3000 Pa, friction angle 25 degrees, gf_I 1 "
                 "J/m^2, gf_II 2 J/m^2") != std::string::npos);
}

TEST_CASE("an interface between two deformable materials opens at its strength and dissipates its gf_I",
          "[interfaces]") {
  // Held at the bottom and pulled up at the top: a uniaxial stress, the same in both layers and
  // on the whole interface, whose joints open as one cohesive crack of area A = 2 m x 1 m. So
  // the top's reaction peaks at f_t A, the broken joints' work is gf_I A, and at the peak the
  // base's top has risen by (sigma / E_base) x 0.5 m. (f_t and gf_I are kBonded's.)
  TempDir dir;
  const RectangleRun run = run_bonded_rectangle(
      dir,
      {"run.end_time=250.0",
       "mechanics.boundary=[{on=\"bottom\", fix=[\"x\", \"y\"]}, {on=\"top\", velocity=[0.0, 1.0e-5]}]"},
      1);
  check_one_cohesive_crack(run, 2.0e3, 1.0, *run.deck.materials.at("base").young);
}

TEST_CASE("an interface between two deformable materials slips at its cohesion and dissipates its gf_II",
          "[interfaces]") {
  // The top pushed along x and every outer side held in y: the held sides carry the
  // complementary shear, so the stress is a simple shear tau, the same in both layers and on
  // the whole interface, whose joints slide as one cohesive crack of area A. So the top's
  // reaction peaks at c A, the broken joints' work is gf_II A and, at the peak, the base's top
  // has moved by (tau / G_base) x 0.5 m, G = E / 2 at nu = 0. The friction angle is 0, so that
  // the strength is c whatever the normal stress the shear's rotation brings
  // (verification/interface_debonding/README.md, the shear run).
  TempDir dir;
  const RectangleRun run = run_bonded_rectangle(
      dir, {"interfaces.base_soil.friction_angle=0.0", "run.end_time=700.0",
            "mechanics.boundary=[{on=\"outer\", fix=[\"y\"]}, {on=\"bottom\", fix=[\"x\", \"y\"]}, "
            "{on=\"top\", velocity=[1.0e-5, 0.0]}]"},
      0);
  check_one_cohesive_crack(run, 3.0e3, 2.0, *run.deck.materials.at("base").young / 2.0);
}
