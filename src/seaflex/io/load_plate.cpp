// ANCF plates in the model file (docs/model-format.md, section 5.3): the `ancf_plate` body,
// its supports (edges simply supported or clamped, nodes pinned or clamped), markers at
// its nodes and the `plate_pressure` load.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "seaflex/constraints/coordinate_lock.hpp"
#include "seaflex/forces/plate_pressure.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

constexpr int kMaxPerEdge = 1000;
constexpr int kMaxPlateElements = 10000;  // 10^4 dense 48x48 blocks: ~180 MB per matrix

const std::vector<std::string> kEdges{"i0", "i_max", "j0", "j_max"};
constexpr const char* kKind[] = {"r", "r_p1", "r_p2", "r_p1p2"};
constexpr const char* kAxis[] = {"x", "y", "z"};

// "n<i>_<j>" -> (i, j); reports a malformed or out-of-range reference at key
std::optional<std::pair<int, int>> plate_node(MapReader& r, std::string_view key,
                                              const AncfPlate& plate) {
  const YAML::Node n = r.get(key, Need::kRequired, "a node n<i>_<j>");
  if (!n.IsDefined()) return std::nullopt;
  const std::string expected = fmt::format(
      "expected a node n<i>_<j> with 0 <= i <= {} and 0 <= j <= {}", plate.nx(), plate.ny());
  if (!n.IsScalar()) {
    r.error(key, fmt::format("{}, got {}", expected, describe(n)));
    return std::nullopt;
  }
  const std::string& s = n.Scalar();
  const auto under = s.find('_');
  auto digits = [](const std::string& t) {
    return !t.empty() && t.size() <= 6 && t.find_first_not_of("0123456789") == std::string::npos;
  };
  if (s.size() < 4 || s[0] != 'n' || under == std::string::npos ||
      !digits(s.substr(1, under - 1)) || !digits(s.substr(under + 1))) {
    r.error(key, fmt::format("{}, got '{}'", expected, s));
    return std::nullopt;
  }
  const int i = std::stoi(s.substr(1, under - 1)), j = std::stoi(s.substr(under + 1));
  if (i > plate.nx() || j > plate.ny()) {
    r.error(key, fmt::format("node {} does not exist: plate '{}' has nodes n0_0 to n{}_{}", s,
                             plate.name(), plate.nx(), plate.ny()));
    return std::nullopt;
  }
  return std::pair(i, j);
}

// the nodes of an edge and the kind (1 r_p1, 2 r_p2) of the slope along it
std::pair<std::vector<std::pair<int, int>>, int> edge_nodes(const AncfPlate& plate,
                                                            const std::string& edge) {
  std::vector<std::pair<int, int>> nodes;
  if (edge == "i0" || edge == "i_max") {
    const int i = edge == "i0" ? 0 : plate.nx();
    for (int j = 0; j <= plate.ny(); ++j) nodes.emplace_back(i, j);
    return {nodes, 2};
  }
  const int j = edge == "j0" ? 0 : plate.ny();
  for (int i = 0; i <= plate.nx(); ++i) nodes.emplace_back(i, j);
  return {nodes, 1};
}

// the coordinate axis a unit vector lies along, or -1
int axis_of(const Vec3& t) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(t[k]) - 1.0) < 1e-12) return k;
  return -1;
}

}  // namespace

std::unique_ptr<Body> build_ancf_plate(MapReader& r, const std::string& name, LoadContext&) {
  bool ok = true;
  PlateGeometry g;
  const auto corner = r.vec3("corner", Need::kRequired, "m");
  const auto edge1 = r.vec3("edge1", Need::kRequired, "m");
  const auto edge2 = r.vec3("edge2", Need::kRequired, "m");
  std::optional<int> nx, ny;
  const YAML::Node el =
      r.get("elements", Need::kRequired, "[n1, n2], the numbers of elements along edge1 and edge2");
  if (el.IsDefined()) {
    if (!el.IsSequence() || el.size() != 2) {
      const std::string got = !el.IsSequence() ? describe(el)
                              : el.size() == 1 ? std::string("1 entry")
                                               : fmt::format("{} entries", el.size());
      r.error("elements", fmt::format("expected [n1, n2], the numbers of elements along edge1 and "
                                      "edge2, got {}",
                                      got));
    } else {
      nx = read_integer(r.diagnostics(), el[0], r.key_path("elements") + "[0]", 1, kMaxPerEdge);
      ny = read_integer(r.diagnostics(), el[1], r.key_path("elements") + "[1]", 1, kMaxPerEdge);
      if (nx && ny && *nx * *ny > kMaxPlateElements) {
        r.error("elements", fmt::format("{} x {} = {} elements exceed the limit of {} per plate",
                                        *nx, *ny, *nx * *ny, kMaxPlateElements));
        ok = false;
      }
    }
  }
  // a rectangle: two non-zero, perpendicular edges
  if (edge1 && !(edge1->norm() > 0.0)) {
    r.error("edge1", "must not be zero: the plate needs a length along its first edge");
    ok = false;
  }
  if (edge2 && !(edge2->norm() > 0.0)) {
    r.error("edge2", "must not be zero: the plate needs a length along its second edge");
    ok = false;
  }
  if (ok && edge1 && edge2) {
    const double c = edge1->normalized().dot(edge2->normalized());
    if (std::abs(c) > 1e-6) {
      const double angle = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
      r.error("edge2", std::abs(c) > 1.0 - 1e-12
                           ? std::string("is parallel to edge1: the rectangle is degenerate")
                           : fmt::format("must be perpendicular to edge1 (the plate is a "
                                         "rectangle); the angle between them is {:.6g} deg",
                                         angle));
      ok = false;
    }
  }

  ancf_plate::PlateMaterial mat;
  const auto h = r.number("thickness", Need::kRequired, NumberRule::positive("m"));
  const auto E = r.number("youngs_modulus", Need::kRequired, NumberRule::positive("Pa"));
  const auto nu = r.number("poisson_ratio", Need::kRequired, NumberRule::any(""));
  const auto rho = r.number("density", Need::kRequired, NumberRule::positive("kg/m^3"));
  if (!check_material(r, E, rho)) ok = false;
  if (nu && !(*nu > -1.0 && *nu < 0.5)) {
    r.error("poisson_ratio",
            fmt::format("must be greater than -1 and less than 0.5 (an isotropic material), "
                        "got {:g}",
                        *nu));
    ok = false;
  }

  PlateOptions options;
  if (const auto m = r.choice("midplane_model", Need::kOptional, {"exact", "L1", "L3"}))
    options.midplane = *m == "L1"   ? ancf_plate::MidplaneModel::kL1
                       : *m == "L3" ? ancf_plate::MidplaneModel::kL3
                                    : ancf_plate::MidplaneModel::kExact;
  if (const auto m = r.choice("transverse_model", Need::kOptional, {"exact", "T2", "T3"}))
    options.transverse = *m == "T2"   ? ancf_plate::TransverseModel::kT2
                         : *m == "T3" ? ancf_plate::TransverseModel::kT3
                                      : ancf_plate::TransverseModel::kExact;
  if (const auto n = r.integer("gauss_points", Need::kOptional, 2, 20)) {
    options.gauss_points = *n;
    if (options.midplane != ancf_plate::MidplaneModel::kExact &&
        options.transverse != ancf_plate::TransverseModel::kExact) {
      r.error("gauss_points",
              "applies only to the exact midplane or transverse model; L1, L3, T2 and T3 are "
              "integrated exactly");
      ok = false;
    }
  }

  if (!ok || !corner || !edge1 || !edge2 || !nx || !ny || !h || !E || !nu || !rho) return nullptr;
  g.corner = *corner;
  g.edge1 = *edge1;
  g.edge2 = *edge2;
  g.nx = *nx;
  g.ny = *ny;
  mat.thickness = *h;
  mat.youngs_modulus = *E;
  mat.poisson_ratio = *nu;
  mat.density = *rho;
  return std::make_unique<AncfPlate>(name, g, mat, options);
}

const AncfPlate* plate_of(const YAML::Node& support, const LoadContext& ctx, bool* skip) {
  *skip = false;
  if (!support.IsMap()) return nullptr;
  const YAML::Node b = support["body"];
  if (!b.IsDefined() || !b.IsScalar()) return nullptr;
  const auto& failed = ctx.failed_bodies;
  if (std::find(failed.begin(), failed.end(), b.Scalar()) != failed.end()) {
    // a body that could not be built (reported there): a support written for a plate is
    // not checked against it
    // (a missing key is a zombie node, on which IsScalar() throws: IsDefined() first)
    const YAML::Node type = support["type"], node = support["node"];
    *skip = support["edges"].IsDefined() || support["in_plane"].IsDefined() ||
            (type.IsDefined() && type.IsScalar() && type.Scalar() == "simply_supported") ||
            (node.IsDefined() && node.IsScalar() && node.Scalar().size() > 1 &&
             node.Scalar()[0] == 'n' && node.Scalar().find('_') != std::string::npos);
    return nullptr;
  }
  return dynamic_cast<const AncfPlate*>(ctx.system.find_body(b.Scalar()));
}

void load_plate_support(MapReader& r, const AncfPlate& plate, const YAML::Node& node,
                        std::set<std::pair<std::string, Index>>& held, LoadContext& ctx) {
  r.text("body", Need::kRequired);
  const auto type = r.choice("type", Need::kRequired, {"simply_supported", "clamped", "pinned"});
  const bool has_edges = r.has("edges"), has_node = r.has("node");
  std::vector<std::string> edges;
  std::optional<std::pair<int, int>> at;
  bool ok = true;
  if (has_edges && has_node) {
    r.error("node", "give either edges or node, not both");
    ok = false;
  } else if (!has_edges && !has_node) {
    r.error("edges", fmt::format("required key is missing (a list of edges from {}, or node: "
                                 "n<i>_<j>)",
                                 fmt::join(kEdges, ", ")));
    ok = false;
  } else if (has_edges) {
    const YAML::Node list = r.get("edges");
    if (type && *type == "pinned") {
      r.error("type", "'pinned' holds one node; an edge is simply_supported or clamped");
      ok = false;
    }
    if (!list.IsSequence() || list.size() == 0) {
      r.error("edges", fmt::format("expected a non-empty list of edges from {}, got {}",
                                   fmt::join(kEdges, ", "),
                                   list.IsSequence() ? "an empty list" : describe(list)));
      ok = false;
    } else {
      for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string path = fmt::format("{}[{}]", r.key_path("edges"), k);
        const std::string s = list[k].IsScalar() ? list[k].Scalar() : describe(list[k]);
        if (std::find(kEdges.begin(), kEdges.end(), s) == kEdges.end()) {
          ctx.diag.error(
              list[k].Mark(), path,
              fmt::format("plate '{}' has no edge '{}'; {} (i0: the nodes n0_<j> at "
                          "the corner, along edge2; i_max: n{}_<j>; j0: the nodes "
                          "n<i>_0, along edge1; j_max: n<i>_{})",
                          plate.name(), s, suggestion(s, kEdges), plate.nx(), plate.ny()));
          ok = false;
        } else if (std::find(edges.begin(), edges.end(), s) != edges.end()) {
          ctx.diag.error(list[k].Mark(), path, fmt::format("edge '{}' is listed twice", s));
          ok = false;
        } else {
          edges.push_back(s);
        }
      }
    }
  } else {
    if (type && *type == "simply_supported") {
      r.error("type", "'simply_supported' applies to edges; a node is pinned or clamped");
      ok = false;
    }
    at = plate_node(r, "node", plate);
    if (!at) ok = false;
  }
  // in_plane: what a simply supported edge holds in the plane of the plate
  std::string in_plane = "fixed";
  if (const auto m = r.choice("in_plane", Need::kOptional, {"fixed", "sliding", "free"})) {
    in_plane = *m;
    if (type && *type != "simply_supported") {
      r.error("in_plane", fmt::format("applies to simply_supported edges only; a {} {} holds all "
                                      "its position components",
                                      *type, has_edges ? "edge" : "node"));
      ok = false;
    } else if (in_plane != "fixed" && (axis_of(plate.t1()) < 0 || axis_of(plate.t2()) < 0)) {
      r.error("in_plane",
              fmt::format("'{}' needs a plate whose edges are along the x, y or z axes (the held "
                          "components are coordinates); plate '{}' has edge1 along ({:.6g}, "
                          "{:.6g}, {:.6g}) and edge2 along ({:.6g}, {:.6g}, {:.6g})",
                          in_plane, plate.name(), plate.t1().x(), plate.t1().y(), plate.t1().z(),
                          plate.t2().x(), plate.t2().y(), plate.t2().z()));
      ok = false;
    }
  }
  r.finish();
  if (!ok || !type) return;

  // (node, kind) pairs held, in order: an edge holds r and the slope along it (its line
  // stays put), clamped also the cross slope and the twist r_p1p2 (the slope across it
  // stays put too); a pinned node r, a clamped node r, r_p1 and r_p2
  // (i, j, kind, component) held; component -1: all three
  std::vector<std::tuple<int, int, int, int>> held_vectors;
  if (at) {
    for (int kind : *type == "clamped" ? std::vector<int>{0, 1, 2} : std::vector<int>{0})
      held_vectors.emplace_back(at->first, at->second, kind, -1);
  } else {
    for (const std::string& edge : edges) {
      const auto [nodes, along] = edge_nodes(plate, edge);
      const int normal = axis_of(plate.normal());
      const int tangent = axis_of(along == 1 ? plate.t1() : plate.t2());
      for (const auto& [i, j] : nodes) {
        if (*type == "clamped" || in_plane == "fixed") {
          for (int kind :
               *type == "clamped" ? std::vector<int>{0, 1, 2, 3} : std::vector<int>{0, along})
            held_vectors.emplace_back(i, j, kind, -1);
          continue;
        }
        for (int kind : {0, along}) {
          held_vectors.emplace_back(i, j, kind, normal);
          if (in_plane == "sliding") held_vectors.emplace_back(i, j, kind, tangent);
        }
      }
    }
  }
  std::vector<Index> locals;
  std::vector<double> values;
  std::vector<std::string> labels;
  for (const auto& [i, j, kind, component] : held_vectors) {
    const auto init = plate.node_initial(i, j);
    for (int c = 0; c < 3; ++c) {
      if (component >= 0 && c != component) continue;
      const Index local = plate.node_local(i, j) + 3 * kind + c;
      // supports of a plate combine: a coordinate held already (a shared corner) is skipped
      if (!held.insert({plate.name(), local}).second) continue;
      locals.push_back(local);
      values.push_back(init[3 * kind + c]);
      labels.push_back(fmt::format("n{}_{}.{}.{}", i, j, kKind[kind], kAxis[c]));
    }
  }
  if (locals.empty()) return;
  std::string cname = at ? fmt::format("support {}.n{}_{}", plate.name(), at->first, at->second)
                         : fmt::format("support {}.{}", plate.name(), fmt::join(edges, "+"));
  if (ctx.constraint_origin.count(cname)) cname += fmt::format(" ({})", r.path());
  ctx.constraint_origin[cname] = {node.Mark(), r.path()};
  ctx.system.add_constraint(std::make_unique<CoordinateLock>(cname, plate, locals, values, labels));
}

std::unique_ptr<Marker> plate_marker(MapReader& r, const AncfPlate& plate) {
  for (const char* k : {"position", "orientation", "axis", "euler_zxz", "arc_length"})
    if (r.has(k))
      r.error(k, fmt::format("a marker on plate '{}' is placed by node (n<i>_<j>); its axes are "
                             "the plate's slopes r_p1, r_p2 and the normal r_p1 x r_p2",
                             plate.name()));
  const auto at = plate_node(r, "node", plate);
  if (!at) return nullptr;
  return std::make_unique<PlateMarker>(plate, at->first, at->second);
}

std::unique_ptr<Force> build_plate_pressure(MapReader& r, const std::string& name,
                                            LoadContext& ctx) {
  const Body* body = ctx.body_ref(r, "body", false, nullptr);
  const auto* plate = dynamic_cast<const AncfPlate*>(body);
  if (body && !plate)
    r.error("body", fmt::format("body '{}' is a {}; only ancf_plate bodies are accepted here",
                                body->name(), body->kind()));
  const auto p = r.number("pressure", Need::kRequired, NumberRule::any("Pa"));
  std::optional<Vec3> direction;
  bool ok = true;
  if (const YAML::Node d = r.get("direction"); d.IsDefined()) {
    if (d.IsScalar() && d.Scalar() == "normal") {
      // the default
    } else if (d.IsSequence()) {
      direction = read_vec3(r.diagnostics(), d, r.key_path("direction"), "(a direction)");
      if (!direction) {
        ok = false;
      } else if (!(direction->norm() > 0.0)) {
        r.error("direction", "the direction must be a non-zero vector");
        ok = false;
      }
    } else {
      r.error("direction",
              fmt::format("expected normal or a vector [x, y, z], got {}", describe(d)));
      ok = false;
    }
  }
  auto factor = read_time_factor(r);
  if (!plate || !p || !factor || !ok) return nullptr;
  return std::make_unique<PlatePressure>(name, *plate, *p, std::move(*factor), direction);
}

}  // namespace seaflex::io
