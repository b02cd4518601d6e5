// Writing a scene back, defaults filled in: the schema and each method put their keys in one ordered tree
// (app/scene_keys.hpp), rendered as TOML (parse_scene reads it again) or through the JSON writer.
#include <cmath>

#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_text.hpp"

namespace contactbench {

void SceneKeys::put(std::string key, Value value) {
  values.emplace_back(std::move(key), std::move(value));
}

namespace {

void write_material_keys(const MaterialSpec& material, bool with_estar, SceneKeys& root) {
  SceneKeys& table = root.table("material");
  if (material.youngs_modulus) {
    table.put("E", *material.youngs_modulus);
    if (material.poisson_ratio) table.put("nu", *material.poisson_ratio);
    if (material.youngs_modulus_2) table.put("E2", *material.youngs_modulus_2);
    if (material.poisson_ratio_2) table.put("nu2", *material.poisson_ratio_2);
    if (with_estar) table.put("estar", material.estar);
  } else {
    table.put("estar", material.estar);
  }
}

SceneKeys scene_keys(const Scene& scene, bool with_estar) {
  SceneKeys root;
  root.put("name", scene.name);
  root.put("description", scene.description);
  root.put("reference", scene.reference);
  if (scene.compare != std::vector<Quantity>{Quantity::area}) {  // the default is not written: old scenes
    std::vector<std::string> names;                              // read back exactly as before
    for (const Quantity q : scene.compare)
      names.emplace_back(quantity_name(q));
    root.put("compare", names);
  }
  write_surface_keys(scene.surface, root);
  write_material_keys(scene.material, with_estar, root);
  write_interface(scene.interface, root);
  SceneKeys& loads = root.table("loads");
  if (scene.load_path.empty()) {
    loads.put("values", scene.loads);
  } else {  // the path as listed, which gives back the sorted loads too
    loads.put("values", scene.load_path);
    loads.put("path", std::string("as listed"));
  }
  if (scene.distributions) {
    SceneKeys& distributions = root.table("distributions");
    distributions.put("load", scene.distributions->load);
    distributions.put("bins", static_cast<std::int64_t>(scene.distributions->bins));
  }
  if (scene.approach_retract) {
    SceneKeys& path = root.table("approach_retract");
    path.put("from", scene.approach_retract->start);
    path.put("to", scene.approach_retract->turn);
    path.put("steps", static_cast<std::int64_t>(scene.approach_retract->steps));
  }
  SceneKeys& methods = root.table("methods");
  for (const MethodSpec& m : scene.methods) {
    SceneKeys& keys = methods.table(m.label);
    keys.put("method", std::string(m.name()));
    if (!m.ignored.empty()) {
      std::vector<std::string> names;
      for (const Effect e : m.ignored)
        names.emplace_back(effect_name(e));
      keys.put("ignore", names);
    }
    m.method->write(keys);
  }
  return root;
}

// ---- TOML: strings and numbers in the JSON writer's forms, which TOML reads too ----

std::string toml_key(const std::string& key) {
  return portable_name(key, false) ? key : json_quote(key);
}

std::string toml_number(Real value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string text = json_number(value);
  // TOML reads "31400" as an integer: a float needs a point or an exponent.
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string toml_value(const SceneKeys::Value& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Real>) {
          return toml_number(v);
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          return std::to_string(v);
        } else if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return json_quote(v);
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          std::string out = "[";
          for (std::size_t i = 0; i < v.size(); ++i)
            out.append(i ? ", " : "").append(json_quote(v[i]));
          return out + "]";
        } else {
          std::string out = "[";
          for (std::size_t i = 0; i < v.size(); ++i)
            out.append(i ? ", " : "").append(toml_number(v[i]));
          return out + "]";
        }
      },
      value);
}

// Plain keys, then each sub-table as its own [section] (a table of tables alone, [methods], needs none).
void render_toml(std::string& out, const SceneKeys& table, const std::string& path) {
  for (const auto& [key, value] : table.values)
    out.append(toml_key(key)).append(" = ").append(toml_value(value)) += '\n';
  for (const SceneKeys& sub : table.tables) {
    const std::string sub_path = path.empty() ? toml_key(sub.name) : path + "." + toml_key(sub.name);
    if (!sub.values.empty() || sub.tables.empty()) out.append("\n[").append(sub_path).append("]\n");
    render_toml(out, sub, sub_path);
  }
}

JsonObject to_json_object(const SceneKeys& table) {
  JsonObject object;
  for (const auto& [key, value] : table.values)
    std::visit(
        [&, &key = key](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::int64_t>)
            object.add(key, static_cast<long long>(v));
          else if constexpr (std::is_same_v<T, std::vector<Real>>)
            object.add(key, std::span<const double>(v));
          else if constexpr (std::is_same_v<T, std::vector<std::string>>)
            object.add(key, std::span<const std::string>(v));
          else if constexpr (std::is_same_v<T, std::string>)
            object.add(key, std::string_view(v));
          else
            object.add(key, v);
        },
        value);
  for (const SceneKeys& sub : table.tables)
    object.add(sub.name, to_json_object(sub));
  return object;
}

}  // namespace

std::string to_toml(const Scene& scene) {
  std::string out = "# contactbench scene as understood, defaults filled in (scenes/README.md)\n";
  render_toml(out, scene_keys(scene, false), "");
  return out;
}

std::string to_json(const Scene& scene) {
  return to_json_object(scene_keys(scene, true)).str() + "\n";
}

}  // namespace contactbench
