// bodies: a mapping of body names to bodies, each with a "type" from the registry.
#include <fmt/format.h>

#include <numeric>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/elements/catenary_shape.hpp"
#include "seaflex/elements/line_catenary.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/beam_attachment.hpp"
#include "seaflex/forces/morison_beam.hpp"
#include "seaflex/io/load_context.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/model/moving_marker.hpp"

namespace seaflex::io {

bool check_material(MapReader& r, std::optional<double> E, std::optional<double> rho) {
  bool ok = true;
  if (E && *E < 1e4) {
    r.error("youngs_modulus",
            fmt::format("{:g} Pa is implausibly low; seaflex uses Pa (steel: 2.1e11), "
                        "not GPa or MPa",
                        *E));
    ok = false;
  }
  if (rho && *rho < 100.0) {
    r.error("density",
            fmt::format("{:g} kg/m^3 is implausibly low; seaflex uses kg/m^3 (steel: 7850), "
                        "not t/m^3",
                        *rho));
    ok = false;
  }
  if (rho && *rho > kMaxDensity) {
    // a unit weight (N/m^3) is the density times g: steel 77,000 N/m^3 = 7850 kg/m^3
    const double as_density = *rho / kStandardGravity;
    r.error("density",
            fmt::format("{:g} kg/m^3 is implausibly high, denser than any material (osmium: "
                        "22,590 kg/m^3){}; seaflex uses kg/m^3 (steel: 7850)",
                        *rho,
                        as_density >= 100.0 && as_density <= kMaxDensity
                            ? fmt::format(": it looks like a unit weight in N/m^3, the density "
                                          "times g ({:g} / 9.80665 = {:.4g} kg/m^3)",
                                          *rho, as_density)
                            : ""));
    ok = false;
  }
  return ok;
}

namespace {

constexpr int kMaxElements = 100000;  // per beam: 600k coordinates, ~1 GB of matrices

// a beam is slender: a diameter above its length (often millimetres given as metres) is
// refused, naming what was probably meant
bool check_slender(MapReader& r, std::string_view key, double diameter, double length) {
  if (!(diameter > length)) return true;
  r.error(key, fmt::format("{:g} m is more than the beam's length ({:g} m): a beam is much longer "
                           "than its diameter; seaflex uses m, not mm ({:g} mm = {:g} m)",
                           diameter, length, diameter, diameter / 1000.0));
  return false;
}

// the material and cross-section that a line's sections take when they do not give their
// own: the beam's own keys (all optional when the beam has sections)
struct SectionDefaults {
  std::optional<double> E, rho;
  std::optional<double> od, id, area, inertia;
};

// youngs_modulus and density, and outer_diameter/inner_diameter or area/second_moment, with
// d's values where a key is absent; length (m) for the slenderness check (0: none)
std::optional<BeamSection> read_cross_section(MapReader& r, const SectionDefaults& d,
                                              double length) {
  bool ok = true;
  auto E = r.number("youngs_modulus", d.E ? Need::kOptional : Need::kRequired,
                    NumberRule::positive("Pa"));
  auto rho = r.number("density", d.rho ? Need::kOptional : Need::kRequired,
                      NumberRule::positive("kg/m^3"));
  if (!check_material(r, E, rho)) ok = false;
  if (!E) E = d.E;
  if (!rho) rho = d.rho;
  const bool has_od = r.has("outer_diameter"), has_id = r.has("inner_diameter");
  const bool has_area = r.has("area"), has_inertia = r.has("second_moment");
  bool pipe = has_od || has_id;
  const bool explicit_section = has_area || has_inertia;
  const bool inherit = !pipe && !explicit_section && (d.od || d.area);
  if (inherit) pipe = d.od.has_value();
  BeamSection section;
  if (pipe && explicit_section) {
    r.error("area",
            "give the section either as outer_diameter/inner_diameter or as area/second_moment, "
            "not both");
    return std::nullopt;
  } else if (pipe) {
    auto od =
        inherit ? d.od : r.number("outer_diameter", Need::kRequired, NumberRule::positive("m"));
    auto id =
        inherit ? d.id : r.number("inner_diameter", Need::kOptional, NumberRule::nonnegative("m"));
    if (od && id && !(*id < *od)) {
      r.error("inner_diameter",
              fmt::format("must be smaller than outer_diameter ({:g} m), got {:g} m", *od, *id));
      ok = false;
    }
    if (od && length > 0.0 && !check_slender(r, "outer_diameter", *od, length)) ok = false;
    if (od && E && rho && ok) section = BeamSection::pipe(*od, id.value_or(0.0), *E, *rho);
  } else {
    const auto A =
        inherit ? d.area : r.number("area", Need::kRequired, NumberRule::positive("m^2"));
    const auto I = inherit
                       ? d.inertia
                       : r.number("second_moment", Need::kRequired, NumberRule::positive("m^4"));
    if (A && I && E && rho) {
      section.area = *A;
      section.second_moment = *I;
      section.youngs_modulus = *E;
      section.density = *rho;
    }
  }
  if (!ok || !(section.area > 0.0)) return std::nullopt;
  return section;
}

// the beam-level keys of a line made of sections, every one optional
std::optional<SectionDefaults> read_section_defaults(MapReader& r) {
  SectionDefaults d;
  d.E = r.number("youngs_modulus", Need::kOptional, NumberRule::positive("Pa"));
  d.rho = r.number("density", Need::kOptional, NumberRule::positive("kg/m^3"));
  if (!check_material(r, d.E, d.rho)) return std::nullopt;
  const bool pipe = r.has("outer_diameter") || r.has("inner_diameter");
  const bool explicit_section = r.has("area") || r.has("second_moment");
  if (pipe && explicit_section) {
    r.error("area",
            "give the section either as outer_diameter/inner_diameter or as area/second_moment, "
            "not both");
    return std::nullopt;
  }
  if (pipe) {
    d.od = r.number("outer_diameter", Need::kRequired, NumberRule::positive("m"));
    d.id = r.number("inner_diameter", Need::kOptional, NumberRule::nonnegative("m"));
    if (!d.od) return std::nullopt;
  } else if (explicit_section) {
    d.area = r.number("area", Need::kRequired, NumberRule::positive("m^2"));
    d.inertia = r.number("second_moment", Need::kRequired, NumberRule::positive("m^4"));
    if (!d.area || !d.inertia) return std::nullopt;
  }
  return d;
}

struct LineSections {
  std::vector<BeamSection> sections;
  std::vector<int> section_of;  // per element
  std::vector<double> element_lengths;
};

// bodies.<name>.sections: the line's sections from its start, each with a length, a
// target segment_length (or a number of elements) and its own cross-section and material
// (the beam's keys are the defaults); a section's `hydrodynamics` map is kept for
// load_beam_hydro (load_ocean.cpp)
std::optional<LineSections> read_line_sections(MapReader& r, const std::string& name,
                                               LoadContext& ctx) {
  const auto defaults = read_section_defaults(r);
  const YAML::Node list = r.get("sections");
  if (!list.IsSequence() || list.size() == 0) {
    r.error("sections",
            fmt::format("expected a list of sections (- {{length: ..., segment_length: ..., "
                        "outer_diameter: ...}}), got {}",
                        list.IsSequence() ? "an empty list" : describe(list)));
    return std::nullopt;
  }
  if (r.has("elements")) {
    r.error("elements", "set per section (segment_length or elements) in a line made of sections");
    return std::nullopt;
  }
  if (!defaults) return std::nullopt;
  LineSections out;
  bool ok = true;
  long total = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    MapReader sr(r.diagnostics(), list[i], fmt::format("{}[{}]", r.key_path("sections"), i));
    if (!sr.valid()) {
      ok = false;
      continue;
    }
    sr.text("name", Need::kOptional);  // a label for the reader of the file
    const auto length = sr.number("length", Need::kRequired, NumberRule::positive("m"));
    const bool by_length = sr.has("segment_length"), by_count = sr.has("elements");
    std::optional<int> n;
    if (by_length && by_count) {
      sr.error("elements", "give either segment_length or elements, not both");
      ok = false;
    } else if (by_count) {
      n = sr.integer("elements", Need::kRequired, 1, kMaxElements);
    } else {
      const auto seg = sr.number("segment_length", Need::kRequired, NumberRule::positive("m"));
      // the fewest equal elements no longer than the target
      if (seg && length) {
        const double count = std::ceil(*length / *seg * (1.0 - 1e-12));
        if (count > kMaxElements) {
          sr.error("segment_length",
                   fmt::format("{:g} m makes {:g} elements of a {:g} m section, more than the "
                               "limit of {} per beam",
                               *seg, count, *length, kMaxElements));
          ok = false;
        } else {
          n = static_cast<int>(std::max(1.0, count));
        }
      }
    }
    const auto sec = read_cross_section(sr, *defaults, length.value_or(0.0));
    if (const YAML::Node h = sr.get("hydrodynamics"); h.IsDefined()) {
      if (ctx.section_hydrodynamics.find(name) == ctx.section_hydrodynamics.end())
        // load_beam_hydro takes them; any left means the beam has no hydrodynamics entry
        ctx.after_bodies.push_back([name](LoadContext& c) {
          const auto it = c.section_hydrodynamics.find(name);
          if (it == c.section_hydrodynamics.end()) return;
          for (const auto& o : it->second)
            c.diag.error(o.node.Mark(), o.path,
                         fmt::format("needs an entry hydrodynamics.{} for the beam (its "
                                     "coefficients are the sections' defaults)",
                                     name));
        });
      ctx.section_hydrodynamics[name].push_back({i, h, sr.key_path("hydrodynamics")});
    }
    sr.finish();
    if (!length || !n || !sec) {
      ok = false;
      continue;
    }
    total += *n;
    if (total > kMaxElements) {
      sr.error("", fmt::format("the sections have more than the limit of {} elements per beam",
                               kMaxElements));
      return std::nullopt;
    }
    out.sections.push_back(*sec);
    out.element_lengths.insert(out.element_lengths.end(), *n, *length / *n);
    out.section_of.insert(out.section_of.end(), *n, static_cast<int>(out.sections.size() - 1));
  }
  if (!ok) return std::nullopt;
  return out;
}

// once the loads and hydrodynamics are read: a slack line whose submerged weight varies
// along it (sections, clumps, buoyancy modules) starts as its weighted catenary
// (elements/line_catenary.hpp) instead of the uniform one; the uniform one stays when the
// weight is uniform or no weighted catenary is found
void reshape_by_weight(const std::string& name, const Vec3& start, const Vec3& end, bool seabed,
                       const BeamGeometry& uniform, const CatenaryShape& shape, LoadContext& ctx) {
  ctx.after_bodies.push_back([=](LoadContext& c) {
    AncfBeam* beam = nullptr;
    for (const auto& b : c.system.bodies())
      if (b->name() == name) beam = dynamic_cast<AncfBeam*>(b.get());
    if (!beam) return;
    const double g = c.model.gravity.norm();
    LineWeights w;
    const MorisonBeam* morison = nullptr;
    for (const auto& f : c.system.forces()) {
      if (const auto* m = dynamic_cast<const MorisonBeam*>(f.get()); m && &m->beam() == beam)
        morison = m;
      if (const auto* a = dynamic_cast<const BeamAttachment*>(f.get()); a && &a->beam() == beam)
        for (const auto& [s, share] : a->load_points())
          w.points.emplace_back(s, share * a->submerged_weight());
    }
    for (int k = 0; k < beam->num_elements(); ++k) {
      double per_length = beam->section(k).mass_per_length() * g;
      if (morison && c.model.ocean) {
        const MorisonBeamCoefficients& mc = morison->coefficients(beam->section_index(k));
        const double rho = c.model.ocean->rho();
        per_length += mc.internal_density * std::numbers::pi / 4 * mc.internal_diameter *
                      mc.internal_diameter * g;
        if (mc.buoyancy) per_length -= rho * g * std::numbers::pi / 4 * mc.diameter * mc.diameter;
      }
      w.per_length.push_back(per_length);
    }
    const bool uniform_weight =
        w.points.empty() && std::all_of(w.per_length.begin(), w.per_length.end(), [&](double x) {
          return std::abs(x - w.per_length.front()) <= 1e-12 * std::abs(w.per_length.front());
        });
    if (uniform_weight) return;
    if (auto better =
            weighted_catenary(start, end, uniform.element_lengths, w, seabed, uniform, shape))
      beam->set_initial_shape(std::move(better->positions), std::move(better->slopes));
  });
}

// the first guess of a line made of sections between start and end: straight when its
// length is the chord's (or shorter: stretched), else its catenary
std::optional<BeamGeometry> line_geometry(MapReader& r, const std::string& name, const Vec3& start,
                                          const Vec3& end, const std::vector<double>& lengths,
                                          LoadContext& ctx, bool* ok) {
  const double L = std::accumulate(lengths.begin(), lengths.end(), 0.0);
  const double chord = (end - start).norm();
  if (const auto given = r.number("length", Need::kOptional, NumberRule::positive("m"));
      given && std::abs(*given - L) > 1e-9 * L) {
    r.error("length", fmt::format("{:g} m, but the sections add up to {:.10g} m", *given, L));
    *ok = false;
    return std::nullopt;
  }
  if (!(chord > 0.0)) {
    r.error("end", "coincides with start: the beam needs a length greater than 0 m");
    *ok = false;
    return std::nullopt;
  }
  if (L <= chord * (1.0 + 1e-12)) {
    if (L < 0.5 * chord) {
      r.error("sections", fmt::format("add up to {:g} m, less than half the distance between "
                                      "start and end ({:g} m): the line would start stretched "
                                      "by more than 100 %",
                                      L, chord));
      *ok = false;
      return std::nullopt;
    }
    // straight, nodes at their arc lengths scaled onto the chord
    BeamGeometry g;
    double s = 0.0;
    const Vec3 t = (end - start) / chord;
    for (std::size_t k = 0; k <= lengths.size(); ++k) {
      g.positions.push_back(start + (s / L) * (end - start));
      g.slopes.push_back(t);
      if (k < lengths.size()) s += lengths[k];
    }
    g.positions.back() = end;
    g.element_lengths = lengths;
    return g;
  }
  std::optional<double> seabed_z;
  if (ctx.model.seabed) {
    const Vec3& lower = start.z() <= end.z() ? start : end;
    seabed_z = ctx.model.seabed->at(lower.x(), lower.y()).height;
  }
  try {
    CatenaryShape shape;
    BeamGeometry g = catenary_geometry(start, end, lengths, seabed_z, &shape);
    reshape_by_weight(name, start, end, seabed_z.has_value(), g, shape, ctx);
    return g;
  } catch (const std::invalid_argument& e) {
    r.error("sections", e.what());
    *ok = false;
    return std::nullopt;
  }
}

std::unique_ptr<Body> build_ancf_beam(MapReader& r, const std::string& name, LoadContext& ctx) {
  bool ok = true;
  // geometry: start/end or polyline
  std::optional<BeamGeometry> geometry;
  // evaluate every has(): each call also registers its key as known
  const bool has_start = r.has("start"), has_end = r.has("end");
  const bool straight = has_start || has_end;
  const bool poly = r.has("polyline");
  const bool has_length = r.has("length");
  const bool has_sections = r.has("sections");
  if (has_sections) {
    // geometry from the sections, below
  } else if (poly && has_length) {
    r.has("elements");
    r.error("length",
            "applies to start and end only: a polyline's unstretched length is its own length");
    ok = false;
  } else if (straight && poly) {
    r.has("elements");
    r.error("polyline", "give either start and end, or polyline, not both");
    ok = false;
  } else if (poly) {
    const YAML::Node pl = r.get("polyline");
    std::vector<Vec3> points;
    if (!pl.IsSequence() || pl.size() < 2) {
      r.error("polyline",
              fmt::format("expected a list of at least two points [x, y, z] in m, got {}",
                          describe(pl)));
      ok = false;
    } else {
      for (std::size_t i = 0; i < pl.size(); ++i) {
        const auto p = read_vec3(r.diagnostics(), pl[i],
                                 fmt::format("{}[{}]", r.key_path("polyline"), i), "m");
        if (p)
          points.push_back(*p);
        else
          ok = false;
      }
    }
    std::vector<int> counts;
    const YAML::Node el =
        r.get("elements", Need::kRequired, "a whole number per segment, or one for all");
    if (el.IsDefined() && el.IsSequence()) {
      if (pl.IsSequence() && el.size() + 1 != pl.size()) {
        r.error("elements", fmt::format("expected {} counts, one per polyline segment, got {}",
                                        pl.size() - 1, el.size()));
        ok = false;
      }
      for (std::size_t i = 0; i < el.size(); ++i) {
        const auto c =
            read_integer(r.diagnostics(), el[i], fmt::format("{}[{}]", r.key_path("elements"), i),
                         1, kMaxElements);
        if (c)
          counts.push_back(*c);
        else
          ok = false;
      }
    } else if (el.IsDefined()) {
      const auto c = read_integer(r.diagnostics(), el, r.key_path("elements"), 1, kMaxElements);
      if (c && pl.IsSequence() && pl.size() >= 2)
        counts.assign(pl.size() - 1, *c);
      else
        ok = false;
    } else {
      ok = false;
    }
    if (ok) {
      for (std::size_t i = 0; i + 1 < points.size(); ++i)
        if (!((points[i + 1] - points[i]).norm() > 0.0)) {
          r.error("polyline",
                  fmt::format("points {} and {} coincide: a segment needs a length", i, i + 1));
          ok = false;
        }
      long total = 0;
      for (int c : counts) total += c;
      if (total > kMaxElements) {
        r.error("elements", fmt::format("{} elements in all exceed the limit of {} per beam", total,
                                        kMaxElements));
        ok = false;
      }
      if (ok) geometry = BeamGeometry::polyline(points, counts);
    }
  } else {
    const auto start = r.vec3("start", Need::kRequired, "m");
    const auto end = r.vec3("end", Need::kRequired, "m");
    const auto n = r.integer("elements", Need::kRequired, 1, kMaxElements);
    if (start && end && (*end - *start).norm() <= 0.0) {
      r.error("end", "coincides with start: the beam needs a length greater than 0 m");
      ok = false;
    }
    const auto length = r.number("length", Need::kOptional, NumberRule::positive("m"));
    if (start && end && n && ok) {
      const double chord = (*end - *start).norm();
      if (!length || *length == chord) {
        geometry = BeamGeometry::straight(*start, *end, *n);
      } else if (*length < chord) {
        // shorter than the chord: straight, and stretched from the start (a pretension)
        if (*length < 0.5 * chord) {
          r.error("length", fmt::format("{:g} m is less than half the distance between start "
                                        "and end ({:g} m): the line would start stretched by "
                                        "more than 100 %",
                                        *length, chord));
          ok = false;
        } else {
          geometry = BeamGeometry::straight(*start, *end, *n);
          geometry->element_lengths.assign(*n, *length / *n);
        }
      } else {
        // longer: a slack line, whose first guess is its catenary (elements/catenary_shape),
        // laid on the seabed under its lower end where it would dip below it
        std::optional<double> seabed_z;
        if (ctx.model.seabed) {
          const Vec3& lower = start->z() <= end->z() ? *start : *end;
          seabed_z = ctx.model.seabed->at(lower.x(), lower.y()).height;
        }
        try {
          CatenaryShape shape;
          geometry = catenary_geometry(*start, *end, *length, *n, seabed_z, &shape);
          reshape_by_weight(name, *start, *end, seabed_z.has_value(), *geometry, shape, ctx);
        } catch (const std::invalid_argument& e) {
          r.error("length", e.what());
          ok = false;
        }
      }
    }
  }

  // section: outer/inner diameter, or area and second moment, and the material; a line
  // made of sections (`sections`) reads them per section, the beam's keys as defaults
  std::vector<BeamSection> sections;
  std::vector<int> section_of;
  if (has_sections) {
    auto line = read_line_sections(r, name, ctx);
    if (!line) {
      ok = false;
    } else if (!has_start || !has_end || poly) {
      r.error("sections", "a line made of sections needs start and end (not a polyline)");
      ok = false;
    } else {
      sections = std::move(line->sections);
      section_of = std::move(line->section_of);
      geometry.reset();
      const auto start = r.vec3("start", Need::kRequired, "m");
      const auto end = r.vec3("end", Need::kRequired, "m");
      if (start && end)
        geometry = line_geometry(r, name, *start, *end, line->element_lengths, ctx, &ok);
    }
  } else {
    const SectionDefaults none;
    const double total = geometry ? std::accumulate(geometry->element_lengths.begin(),
                                                    geometry->element_lengths.end(), 0.0)
                                  : 0.0;
    if (auto sec = read_cross_section(r, none, total))
      sections.push_back(*sec);
    else
      ok = false;
    if (geometry) section_of.assign(geometry->element_lengths.size(), 0);
  }

  BeamOptions options;
  if (const auto m = r.choice("axial_model", Need::kOptional, {"exact", "L1", "L2"}))
    options.axial = *m == "L1"   ? ancf_cable::AxialModel::kL1
                    : *m == "L2" ? ancf_cable::AxialModel::kL2
                                 : ancf_cable::AxialModel::kExact;
  if (const auto m =
          r.choice("bending_model", Need::kOptional, {"exact", "exact_deformed", "T1", "T2"}))
    options.bending = *m == "T1"               ? ancf_cable::BendingModel::kT1
                      : *m == "T2"             ? ancf_cable::BendingModel::kT2
                      : *m == "exact_deformed" ? ancf_cable::BendingModel::kExactDeformed
                                               : ancf_cable::BendingModel::kExact;
  const bool exact_bending = options.bending == ancf_cable::BendingModel::kExact ||
                             options.bending == ancf_cable::BendingModel::kExactDeformed;
  if (const auto g = r.integer("gauss_points", Need::kOptional, 2, 20)) {
    options.gauss_points = *g;
    if (options.axial != ancf_cable::AxialModel::kExact && !exact_bending) {
      r.error("gauss_points",
              "applies only to the exact axial or bending model; L1, L2, T1 and "
              "T2 are closed forms");
      ok = false;
    }
  }
  if (options.axial == ancf_cable::AxialModel::kL1 && exact_bending) {
    // L1 restrains only the chord length, the exact curvature only r' x r'': the length of
    // each nodal slope r' would have no stiffness (a singular tangent)
    r.error("axial_model",
            "L1 needs bending_model T1 or T2: with the exact curvature nothing "
            "restrains the length of the nodal slopes r'");
    ok = false;
  }

  if (!ok || !geometry || sections.empty()) return nullptr;
  return std::make_unique<AncfBeam>(name, std::move(*geometry), std::move(sections),
                                    std::move(section_of), options);
}

// inertia: [Ixx, Iyy, Izz] (principal) or the full symmetric 3x3 tensor, about the centre of
// gravity in body axes; must be a physical inertia (positive definite, triangle inequality)
std::optional<Mat3> read_inertia(MapReader& r) {
  const YAML::Node n =
      r.get("inertia", Need::kRequired,
            "[Ixx, Iyy, Izz] or [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]");
  if (!n.IsDefined()) return std::nullopt;
  const std::string hint =
      "expected [Ixx, Iyy, Izz] or the 3x3 tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], "
      "[Ixz, Iyz, Izz]] in kg m^2";
  Mat3 I = Mat3::Zero();
  if (n.IsSequence() && n.size() == 3 && n[0].IsScalar()) {
    const auto d = read_vec3(r.diagnostics(), n, r.key_path("inertia"), "kg m^2");
    if (!d) return std::nullopt;
    I.diagonal() = *d;
  } else if (n.IsSequence() && n.size() == 3) {
    for (int i = 0; i < 3; ++i) {
      const auto row = read_vec3(r.diagnostics(), n[i],
                                 fmt::format("{}[{}]", r.key_path("inertia"), i), "kg m^2");
      if (!row) return std::nullopt;
      I.row(i) = row->transpose();
    }
    const double scale = I.cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (std::abs(I(i, j) - I(j, i)) > 1e-9 * scale) {
          r.error("inertia", fmt::format("the inertia tensor must be symmetric: entry [{}][{}] = "
                                         "{:g} but [{}][{}] = {:g}",
                                         i, j, I(i, j), j, i, I(j, i)));
          return std::nullopt;
        }
  } else {
    r.error("inertia", fmt::format("{}, got {}", hint, describe(n)));
    return std::nullopt;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
  const Vec3 p = eig.eigenvalues();
  if (!(p[0] > 0.0)) {
    r.error("inertia", fmt::format("the inertia tensor is not positive definite (principal "
                                   "moments {:.6g}, {:.6g}, {:.6g} kg m^2)",
                                   p[0], p[1], p[2]));
    return std::nullopt;
  }
  if (p[0] + p[1] < p[2] * (1.0 - 1e-9)) {
    r.error("inertia", fmt::format("principal moments {:.6g}, {:.6g}, {:.6g} kg m^2 violate the "
                                   "triangle inequality I1 + I2 >= I3 that every real body meets",
                                   p[0], p[1], p[2]));
    return std::nullopt;
  }
  return I;
}

std::unique_ptr<Body> build_rigid_body(MapReader& r, const std::string& name, LoadContext& ctx) {
  const auto mass = r.number("mass", Need::kRequired, NumberRule::positive("kg"));
  const auto inertia = read_inertia(r);
  auto position = r.vec3("position", Need::kRequired, "m");
  RigidBodyInitial init;
  bool ok = true;
  if (const auto o = read_orientation(r, false))
    init.orientation = *o;
  else
    ok = false;
  if (r.has("velocity")) {
    if (const auto v = r.vec3("velocity", Need::kRequired, "m/s"))
      init.velocity = *v;
    else
      ok = false;
  }
  if (r.has("angular_velocity")) {
    if (const auto w = r.vec3("angular_velocity", Need::kRequired, "deg/s"))
      init.angular_velocity = *w * (std::numbers::pi / 180.0);
    else
      ok = false;
  }
  // motion: free (default) or imposed; the RAO frame is the global frame (rao_motion.hpp)
  const auto motion = read_motion(r, "motion", position.value_or(Vec3::Zero()), true, ctx);
  if (!motion) ok = false;
  if (motion && motion->motion) {
    if (r.has("velocity") || r.has("angular_velocity"))
      r.error(r.has("velocity") ? "velocity" : "angular_velocity",
              "a body with an imposed motion takes its velocity from the motion; remove "
              "velocity and angular_velocity or set motion: free");
    const YAML::Node mn = r.get("motion");
    const YAML::Node type = mn["type"];
    if (type.IsScalar() && type.Scalar() == "rao" &&
        std::abs(math::roll_pitch_yaw_from_rotation(init.orientation)[2]) > 1e-12)
      r.error("orientation",
              "a body driven by RAOs must not be turned in yaw: its RAO "
              "headings are the global wave directions");
    if (position) {
      ctx.prescribed[name] = {*motion, r.get("motion").Mark(), *position, init.orientation};
      // the body starts on the motion at t = 0: its pose and velocities
      const MotionPose pose = compute_motion_pose(motion->motion->sample(0.0));
      const MovingVector p = displaced_point(pose, motion->origin, *position);
      const Mat3 W = pose.R_t * pose.R.transpose();  // w~ = R' R^T
      init.velocity = p.rate;
      init.angular_velocity = Vec3(W(2, 1), W(0, 2), W(1, 0));
      init.orientation = pose.R * init.orientation;
      position = p.value;
    }
  }
  if (!mass || !inertia || !position || !ok) return nullptr;
  init.position = *position;
  return std::make_unique<RigidBody>(name, *mass, *inertia, init);
}

// the body follows the motion: a fixed joint from a moving ground marker (the body's
// reference point and axes at rest, displaced by the motion) to the body; its reaction
// channels <body>.motion.fx ... mz are the wrench the motion exerts on the body
void add_prescribed_body(const RigidBody& body, const LoadContext::Prescribed& pre,
                         const std::string& path, LoadContext& ctx) {
  auto from = std::make_unique<MovingMarker>(pre.motion.motion, pre.motion.origin,
                                             pre.rest_position, pre.rest_orientation);
  auto to = std::make_unique<RigidBodyMarker>(body, Vec3::Zero());
  const std::string name = body.name() + ".motion";
  ctx.constraint_origin[name] = {pre.mark, path + ".motion"};
  ctx.system.add_constraint(
      std::make_unique<Joint>(name, JointType::kFixed, std::move(from), std::move(to)));
}

}  // namespace

const std::map<std::string, BodyBuilder>& body_builders() {
  static const std::map<std::string, BodyBuilder> builders{
      {"ancf_beam", build_ancf_beam},
      {"rigid_body", build_rigid_body},
      {"ancf_plate", build_ancf_plate},
  };
  return builders;
}

void load_bodies(const YAML::Node& node, LoadContext& ctx) {
  MapReader bodies(ctx.diag, node, "bodies");
  if (!bodies.valid()) return;
  if (node.size() == 0) bodies.error("", "the model has no bodies");
  // a bound on the model's size, so that no model file can exhaust the memory: 2e6
  // coordinates (333,000 beam elements) take about 2 GB in the Newton matrix. Checked
  // body by body (each is bounded too), so that building stops before it is exceeded.
  constexpr long kMaxCoordinates = 2000000;
  long coordinates = 0;
  bool too_big = false;
  for (const auto& kv : node) {
    if (coordinates > kMaxCoordinates) {
      if (!too_big)
        ctx.diag.error(kv.first.Mark(), "bodies." + kv.first.Scalar(),
                       fmt::format("the bodies before this one have {} coordinates together, "
                                   "more than the limit of {:g}: use fewer elements",
                                   coordinates, static_cast<double>(kMaxCoordinates)));
      too_big = true;
      ctx.failed_bodies.push_back(kv.first.Scalar());  // references to it are not reported
      continue;
    }
    const std::string name = kv.first.Scalar();
    bodies.has(name);  // every entry is a body: no unknown keys at this level
    const std::string path = name_key("bodies", name);
    if (name == kGroundName) {
      ctx.diag.error(kv.first.Mark(), path,
                     "'ground' is reserved for the fixed world frame; give the body another name");
      ctx.failed_bodies.push_back(name);
      continue;
    }
    if (const std::string problem = name_problem(name, "body", "<body>.n0.x"); !problem.empty()) {
      ctx.diag.error(kv.first.Mark(), path, problem);
      ctx.failed_bodies.push_back(name);
      continue;
    }
    MapReader r(ctx.diag, kv.second, path);
    if (!r.valid()) continue;
    const auto type = r.choice("type", Need::kRequired, keys_of(body_builders()));
    if (!type) {
      ctx.failed_bodies.push_back(name);
      continue;  // unknown keys cannot be judged without a type
    }
    std::unique_ptr<Body> body = body_builders().at(*type)(r, name, ctx);
    r.finish();
    if (body && !ctx.system.find_body(name)) {
      coordinates += body->num_coordinates();
      const Body& added = *body;
      ctx.system.add_body(std::move(body));
      if (const auto it = ctx.prescribed.find(name); it != ctx.prescribed.end())
        add_prescribed_body(dynamic_cast<const RigidBody&>(added), it->second, path, ctx);
    } else
      ctx.failed_bodies.push_back(name);
  }
}

}  // namespace seaflex::io
