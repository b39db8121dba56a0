#include "seaflex/io/model_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "seaflex/forces/gravity.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

const AncfBeam* LoadContext::beam_ref(MapReader& reader, std::string_view key) {
  const auto name = reader.text(key, Need::kRequired);
  if (!name) return nullptr;
  const Body* body = system.find_body(*name);
  if (!body && std::find(failed_bodies.begin(), failed_bodies.end(), *name) != failed_bodies.end())
    return nullptr;  // already reported where the body is defined
  if (!body) {
    std::vector<std::string> names;
    for (const auto& b : system.bodies()) names.push_back(b->name());
    reader.error(key, names.empty()
                          ? fmt::format("no body named '{}': the model has no valid bodies", *name)
                          : fmt::format("no body named '{}'; {}", *name, suggestion(*name, names)));
    return nullptr;
  }
  const auto* beam = dynamic_cast<const AncfBeam*>(body);
  if (!beam)
    reader.error(key, fmt::format("body '{}' is a {}; only ancf_beam bodies are accepted here",
                                  *name, body->kind()));
  return beam;
}

std::optional<int> LoadContext::node_ref(MapReader& reader, std::string_view key,
                                         const AncfBeam& beam, Need need) {
  const YAML::Node n = reader.get(key, need, "a node number, start or end");
  if (!n.IsDefined()) return std::nullopt;
  if (n.IsScalar() && n.Scalar() == "start") return 0;
  if (n.IsScalar() && n.Scalar() == "end") return beam.num_nodes() - 1;
  const int last = beam.num_nodes() - 1;
  if (!n.IsScalar()) {
    reader.error(key, fmt::format("expected a node number (0..{}), start or end; got {}", last,
                                  describe(n)));
    return std::nullopt;
  }
  {
    const std::string& s = n.Scalar();
    const bool digits = !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) {
      reader.error(key,
                   fmt::format("expected a node number (0..{}), start or end; got '{}'", last, s));
      return std::nullopt;
    }
  }
  return read_integer(diag, n, reader.key_path(key), 0, last);
}

namespace {

Model load(const YAML::Node& root, const std::string& name) {
  Diagnostics diag(name);
  Model model;
  model.file = name;
  model.system = std::make_unique<System>();
  LoadContext ctx{diag, *model.system, model, {}};

  MapReader top(diag, root, "");
  if (!top.valid()) diag.throw_if_any();
  if (const auto title = top.text("title", Need::kOptional)) model.title = *title;

  // environment: gravity magnitude along -z, or a vector
  model.gravity = Vec3(0, 0, -kStandardGravity);
  if (const YAML::Node env = top.get("environment"); env.IsDefined()) {
    MapReader r(diag, env, "environment");
    if (const YAML::Node g = r.get("gravity"); g.IsDefined()) {
      if (g.IsSequence()) {
        if (const auto v = read_vec3(diag, g, "environment.gravity", "m/s^2")) model.gravity = *v;
      } else if (const auto m = read_number(diag, g, "environment.gravity",
                                            NumberRule::range(0.0, 100.0, "m/s^2"))) {
        model.gravity = Vec3(0, 0, *m > 0.0 ? -*m : 0.0);
      }
    }
    r.finish();
  }

  const YAML::Node bodies = top.get("bodies", Need::kRequired, "a mapping of body names to bodies");
  if (bodies.IsDefined()) load_bodies(bodies, ctx);
  if (const YAML::Node n = top.get("supports"); n.IsDefined()) load_supports(n, ctx);
  if (const YAML::Node n = top.get("loads"); n.IsDefined()) load_loads(n, ctx);
  if (model.gravity.norm() > 0.0) {
    std::vector<const Body*> all;
    for (const auto& b : model.system->bodies()) all.push_back(b.get());
    model.system->add_force(std::make_unique<Gravity>(model.gravity, all));
  }
  if (const YAML::Node n = top.get("statics"); n.IsDefined()) load_statics(n, ctx);
  if (const YAML::Node n = top.get("dynamics"); n.IsDefined()) load_dynamics(n, ctx);
  top.finish();
  diag.throw_if_any();
  model.system->finalize();
  return model;
}

YAML::Node parse(const std::string& text, const std::string& name) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    Diagnostics diag(name);
    diag.error(e.mark, "", fmt::format("YAML syntax error: {}", e.msg));
    diag.throw_if_any();
  }
  return {};
}

}  // namespace

Model load_model_text(const std::string& text, const std::string& name) {
  const YAML::Node root = parse(text, name);
  if (!root.IsDefined() || root.IsNull()) {
    Diagnostics diag(name);
    diag.error(YAML::Mark::null_mark(), "", "the model file is empty");
    diag.throw_if_any();
  }
  return load(root, name);
}

Model load_model_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Diagnostics diag(path);
    diag.error(YAML::Mark::null_mark(), "", "cannot open the model file");
    diag.throw_if_any();
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return load_model_text(buffer.str(), path);
}

}  // namespace seaflex::io
