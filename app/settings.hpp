// One declaration per setting (docs/architecture.md, "Each setting declared once"): its key, type, default,
// accepted values, unit, one-line meaning, command-line flag, and whether the distributed solver takes it,
// from which the scene reader and writer, the command's flags, the Python keywords, the MPI packing and its
// refusals are all made (app/settings.cpp), and against which the key tables of scenes/README.md are checked
// (tests/test_settings.cpp). A setting is a row of a table over one options struct, `Owner`; the row reaches
// its member through an accessor, so nested option structs (the solver's own) need no copy of their fields.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "contactbench/app/section.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

enum class SettingKind { boolean, integer, number, choice, text };

// A setting's value as every front end sees it: a choice is its name, an integer a std::int64_t.
using SettingValue = std::variant<bool, std::int64_t, double, std::string>;

// Which settings an operation acts on: those of the solve (methods whose solve settings are equal share
// one solve) or those of the method alone (how it reads the solve: spot connectivity, compared area...).
enum class SettingScope { solve, method };

// The command-line form: `--name VALUE`, or a switch `--name` that sets `sets` (e.g. --float sets
// precision = "single"). No name: not on the command line.
struct SettingFlag {
  std::string name;
  std::optional<SettingValue> sets = std::nullopt;
};

template <class Owner>
struct Setting {
  std::string key = {};  // the scene key, and the Python keyword
  SettingKind kind = SettingKind::number;
  SettingScope scope = SettingScope::solve;
  std::string unit = {};      // "Pa", "m", "" when dimensionless
  std::string accepted = {};  // what messages and the docs say is accepted, e.g. "[1e-13, 0.01]"
  // The default an owner starts from (none: unset, its default comes from elsewhere), and what the docs'
  // default column says when it needs more than the value (e.g. "1e-8 (1e-6 in single precision)").
  std::optional<SettingValue> default_value = std::nullopt;
  std::string default_text = {};
  std::string doc = {};  // one line: what it means
  SettingFlag flag = {};
  bool python = false;  // a keyword of the Python solver object (a per-solve setting a user sets there)
  // Whether the distributed solver takes it: all values, none but the default, or these choices.
  bool distributed = false;
  std::vector<std::string> distributed_choices = {};
  std::vector<std::string> choices = {};  // kind choice
  // Read by its owner, not by read_settings: a range that depends on the scene (refine: the surface's
  // points a side; fields: a path relative to the scene file). Written, documented and flagged like any.
  bool owner_reads = false;
  std::function<bool(const SettingValue&)> ok = nullptr;  // the accepted range; none: every value of its kind
  // The value held, nullopt when unset (its default comes from elsewhere, e.g. the surface's periodicity).
  std::function<std::optional<SettingValue>(const Owner&)> get = nullptr;
  std::function<void(Owner&, const SettingValue&)> set = nullptr;
};

template <class Owner>
using SettingTable = std::vector<Setting<Owner>>;

// ---- Making rows: `field` binds a member through an accessor returning a reference to it ----------------

template <class Owner, class Field>
Setting<Owner> bind(Setting<Owner> row, Field field) {
  row.get = [field](const Owner& o) -> std::optional<SettingValue> {
    const auto& value = field(const_cast<Owner&>(o));  // read only
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, std::optional<bool>>) {
      return value ? std::optional<SettingValue>(*value) : std::nullopt;
    } else if constexpr (std::is_same_v<T, std::optional<Real>>) {
      return value ? std::optional<SettingValue>(*value) : std::nullopt;
    } else if constexpr (std::is_same_v<T, bool>) {
      return SettingValue(value);
    } else if constexpr (std::is_same_v<T, std::string>) {
      return value.empty() ? std::nullopt : std::optional<SettingValue>(value);
    } else if constexpr (std::is_floating_point_v<T>) {
      return SettingValue(static_cast<double>(value));
    } else {
      return SettingValue(static_cast<std::int64_t>(value));
    }
  };
  row.set = [field](Owner& o, const SettingValue& v) {
    auto& value = field(o);
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, std::optional<bool>> || std::is_same_v<T, bool>)
      value = std::get<bool>(v);
    else if constexpr (std::is_same_v<T, std::optional<Real>> || std::is_floating_point_v<T>)
      value = std::get<double>(v);
    else if constexpr (std::is_same_v<T, std::string>)
      value = std::get<std::string>(v);
    else
      value = static_cast<T>(std::get<std::int64_t>(v));
  };
  return row;
}

template <class T>
struct ChoiceField {  // a choice held as T itself
  using type = T;
};
template <class T>
struct ChoiceField<std::optional<T>> {  // or unset, its default resolved elsewhere (e.g. boundary)
  using type = T;
};

// A choice stored as an enum or a bool (the index of its name in `choices`), or as an optional one.
template <class Owner, class Field>
Setting<Owner> bind_choice(Setting<Owner> row, Field field) {
  const std::vector<std::string> names = row.choices;
  row.get = [field, names](const Owner& o) -> std::optional<SettingValue> {
    const auto& value = field(const_cast<Owner&>(o));  // read only
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, typename ChoiceField<T>::type>) {
      return SettingValue(names.at(static_cast<std::size_t>(value)));
    } else {
      if (!value) return std::nullopt;
      return SettingValue(names.at(static_cast<std::size_t>(*value)));
    }
  };
  row.set = [field, names](Owner& o, const SettingValue& v) {
    auto& value = field(o);
    using T = typename ChoiceField<std::decay_t<decltype(value)>>::type;
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == std::get<std::string>(v)) value = static_cast<T>(k);
  };
  return row;
}

// A closed range [low, high] of a number or an integer, as the docs say it.
std::function<bool(const SettingValue&)> in_range(double low, double high);

// ---- What is made from a table (app/settings.cpp) ---------------------------------------------------------

// "a number", "an integer", "true or false", "a string", for messages.
std::string kind_text(SettingKind kind);
// "1e-08", "true", "\"single\"": a value as a scene file writes it.
std::string value_text(const SettingValue& value);

// The row with this key, or null.
template <class Owner>
const Setting<Owner>* find_setting(const SettingTable<Owner>& table, std::string_view key) {
  for (const Setting<Owner>& row : table)
    if (row.key == key) return &row;
  return nullptr;
}

// An owner with every row's default set.
template <class Owner>
Owner default_settings(const SettingTable<Owner>& table) {
  Owner owner{};
  for (const Setting<Owner>& row : table)
    if (row.default_value) row.set(owner, *row.default_value);
  return owner;
}

// Whether two owners agree on every setting of `scope`.
template <class Owner>
bool same_settings(const SettingTable<Owner>& table, SettingScope scope, const Owner& a, const Owner& b) {
  for (const Setting<Owner>& row : table)
    if (row.scope == scope && row.get(a) != row.get(b)) return false;
  return true;
}

// The owner's settings of `scope` set to `from`'s.
template <class Owner>
void copy_settings(const SettingTable<Owner>& table, SettingScope scope, const Owner& from, Owner& to) {
  for (const Setting<Owner>& row : table)
    if (row.scope == scope)
      if (const auto value = row.get(from)) row.set(to, *value);
}

// The settings the distributed solver does not take, each "key = value" (empty: it takes them all).
template <class Owner>
std::vector<std::string> undistributed_settings(const SettingTable<Owner>& table, const Owner& owner,
                                                const Owner& defaults) {
  std::vector<std::string> refused;
  for (const Setting<Owner>& row : table) {
    if (row.scope != SettingScope::solve) continue;
    const auto value = row.get(owner);
    if (!value) continue;
    const bool taken = row.distributed_choices.empty()
                           ? row.distributed || value == row.get(defaults)
                           : std::find(row.distributed_choices.begin(), row.distributed_choices.end(),
                                       std::get<std::string>(*value)) != row.distributed_choices.end();
    if (!taken) refused.push_back(row.key + " = " + value_text(*value));
  }
  return refused;
}

// The solve settings the distributed solver takes, as numbers (a choice by its index) for one broadcast,
// and back. Text (a file prefix) and unset values stay with rank 0, which handles them.
template <class Owner>
bool packed(const Setting<Owner>& row) {
  return row.scope == SettingScope::solve && row.kind != SettingKind::text && row.default_value &&
         (row.distributed || !row.distributed_choices.empty());
}

template <class Owner>
void pack_settings(const SettingTable<Owner>& table, const Owner& owner, std::vector<double>& out) {
  for (const Setting<Owner>& row : table) {
    if (!packed(row)) continue;
    const SettingValue value = row.get(owner).value();
    if (row.kind == SettingKind::choice) {
      const auto at = std::find(row.choices.begin(), row.choices.end(), std::get<std::string>(value));
      out.push_back(static_cast<double>(at - row.choices.begin()));
    } else if (const auto* b = std::get_if<bool>(&value)) {
      out.push_back(*b ? 1.0 : 0.0);
    } else if (const auto* i = std::get_if<std::int64_t>(&value)) {
      out.push_back(static_cast<double>(*i));
    } else {
      out.push_back(std::get<double>(value));
    }
  }
}

template <class Owner>
void unpack_settings(const SettingTable<Owner>& table, const std::vector<double>& in, std::size_t& next,
                     Owner& owner) {
  for (const Setting<Owner>& row : table) {
    if (!packed(row)) continue;
    const double number = in.at(next++);
    switch (row.kind) {
      case SettingKind::choice:
        row.set(owner, row.choices.at(static_cast<std::size_t>(number)));
        break;
      case SettingKind::boolean:
        row.set(owner, number != 0);
        break;
      case SettingKind::integer:
        row.set(owner, static_cast<std::int64_t>(number));
        break;
      default:
        row.set(owner, number);
    }
  }
}

// The row of the scene keys' table in scenes/README.md: | `key` | type [unit] | accepted | default | meaning
// |.
template <class Owner>
std::string markdown_row(const Setting<Owner>& row) {
  const char* types[] = {"boolean", "integer", "number", "string", "string"};
  const std::string default_column = !row.default_text.empty() ? row.default_text
                                     : row.default_value       ? "`" + value_text(*row.default_value) + "`"
                                                               : "none";
  const std::string accepted = !row.accepted.empty()              ? row.accepted
                               : row.kind == SettingKind::boolean ? "`true`, `false`"
                                                                  : "any";
  return "| `" + row.key + "` | " + types[static_cast<int>(row.kind)] +
         (row.unit.empty() ? "" : " [" + row.unit + "]") + " | " + accepted + " | " + default_column + " | " +
         row.doc + " |";
}

// ---- Scenes, command lines, Python: the parts that need no knowledge of the owner -------------------------

struct SceneKeys;

// What a front end needs of a row, without its owner.
struct SettingSpec {
  std::string key;
  SettingKind kind = SettingKind::number;
  std::vector<std::string> choices;
  std::function<bool(const SettingValue&)> ok;
  std::string accepted;
  SettingFlag flag;
  std::string doc;
  std::string unit;
  std::string default_text;  // as the docs say it
};

template <class Owner>
SettingSpec spec_of(const Setting<Owner>& row) {
  return {row.key,
          row.kind,
          row.choices,
          row.ok,
          row.accepted,
          row.flag,
          row.doc,
          row.unit,
          !row.default_text.empty() ? row.default_text
          : row.default_value       ? value_text(*row.default_value)
                                    : "none"};
}

// The value of `spec.key` in the section when present and valid; every problem reported at its key path.
std::optional<SettingValue> read_setting(const Section& section, const SettingSpec& spec);

// Every row's key read from the section into `owner`; returns the keys given. Unknown keys are the
// caller's to reject (the section may hold keys of other declarations too).
template <class Owner>
std::vector<std::string> read_settings(const Section& section, const SettingTable<Owner>& table,
                                       Owner& owner) {
  std::vector<std::string> given;
  for (const Setting<Owner>& row : table)
    if (row.owner_reads) {
      if (section.has(row.key)) given.push_back(row.key);
    } else if (const auto value = read_setting(section, spec_of(row))) {
      row.set(owner, *value);
      given.push_back(row.key);
    }
  return given;
}

void put_setting(SceneKeys& keys, const std::string& key, const SettingValue& value);

// Every set row written back, in declaration order (an unset one, e.g. periodic, is left to its default).
template <class Owner>
void write_settings(SceneKeys& keys, const SettingTable<Owner>& table, const Owner& owner) {
  for (const Setting<Owner>& row : table)
    if (const auto value = row.get(owner)) put_setting(keys, row.key, *value);
}

// A value from a Python keyword or a command line's text, checked as a scene's would be; Error naming
// `where` and the accepted values otherwise. An integer is taken where a number is expected.
SettingValue checked_setting(const SettingSpec& spec, SettingValue value, const std::string& where);

}  // namespace contactbench
