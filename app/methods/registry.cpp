#include "contactbench/app/methods/registry.hpp"

#include <algorithm>

#include "contactbench/app/scene_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

// The built-in methods, each made by the one function its file defines (app/methods/<name>_method.cpp).
std::unique_ptr<Method> make_bem_method();
std::unique_ptr<Method> make_plateau_method();
std::unique_ptr<Method> make_plateau_hertz_method();
std::unique_ptr<Method> make_gw_mccool_method();
std::unique_ptr<Method> make_bgt_method();
std::unique_ptr<Method> make_bgt_linear_method();
std::unique_ptr<Method> make_persson_method();
std::unique_ptr<Method> make_fuller_tabor_method();
std::unique_ptr<Method> make_maugis_gw_method();
std::unique_ptr<Method> make_plateau_kendall_method();
std::unique_ptr<Method> make_plateau_hertz_jkr_method();
std::unique_ptr<Method> make_plateau_capped_method();
std::unique_ptr<Method> make_plateau_hertz_capped_method();
std::unique_ptr<Method> make_persson_plastic_method();
std::unique_ptr<Method> make_ceb_method();
std::unique_ptr<Method> make_kogut_etsion_method();
std::unique_ptr<Method> make_majumdar_bhushan_method();

MethodRegistry& MethodRegistry::global() {
  static MethodRegistry registry = [] {
    MethodRegistry built_in;
    built_in.add("bem", make_bem_method);
    built_in.add("plateau", make_plateau_method);
    built_in.add("plateau_hertz", make_plateau_hertz_method);  // the project's variant, not the paper's
    built_in.add("gw_mccool", make_gw_mccool_method);
    built_in.add("bgt", make_bgt_method);
    built_in.add("bgt_linear", make_bgt_linear_method);
    built_in.add("persson", make_persson_method);
    built_in.add("fuller_tabor", make_fuller_tabor_method);        // adhesive: GW summits each a JKR sphere
    built_in.add("maugis_gw", make_maugis_gw_method);              // adhesive: GW summits each Maugis-Dugdale
    built_in.add("plateau_kendall", make_plateau_kendall_method);  // adhesive, the project's: Kendall punches
    built_in.add("plateau_hertz_jkr", make_plateau_hertz_jkr_method);  // adhesive, the project's: JKR tips
    built_in.add("plateau_capped",
                 make_plateau_capped_method);  // plastic, the project's: plateaus capped at H
    built_in.add("plateau_hertz_capped", make_plateau_hertz_capped_method);  // plastic, the project's
    built_in.add("persson_plastic",
                 make_persson_plastic_method);               // plastic: Persson 2001 with a yield stress
    built_in.add("ceb", make_ceb_method);                    // plastic: Chang-Etsion-Bogy 1987 on GW summits
    built_in.add("kogut_etsion", make_kogut_etsion_method);  // plastic: Kogut-Etsion 2002 on GW summits
    built_in.add("majumdar_bhushan",
                 make_majumdar_bhushan_method);  // plastic: the fractal model the seed cites
    return built_in;
  }();
  return registry;
}

void MethodRegistry::add(std::string name, MethodFactory factory) {
  if (!portable_name(name, false))
    throw Error("method registry: \"" + name + "\" is not a method name (letters, digits, '_', '-')");
  if (make(name)) throw Error("method registry: a method named \"" + name + "\" exists already");
  entries_.push_back({std::move(name), std::move(factory)});
}

void MethodRegistry::remove(std::string_view name) {
  std::erase_if(entries_, [&](const Entry& entry) { return entry.name == name; });
}

std::unique_ptr<Method> MethodRegistry::make(std::string_view name) const {
  for (const Entry& entry : entries_)
    if (entry.name == name) return entry.factory();
  return nullptr;
}

std::vector<std::string> MethodRegistry::names() const {
  std::vector<std::string> names;
  for (const Entry& entry : entries_)
    names.push_back(entry.name);
  return names;
}

std::string MethodRegistry::names_text() const {
  return join(names());
}

}  // namespace contactbench
