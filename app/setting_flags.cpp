#include "contactbench/app/setting_flags.hpp"

#include <charconv>

#include "contactbench/app/output.hpp"

namespace contactbench {

SettingFlags::SettingFlags(std::vector<SettingSpec> specs)
    : specs_(std::move(specs)), texts_(specs_.size()), switched_(specs_.size(), false) {}

void SettingFlags::add_to(CLI::App& command) {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const SettingSpec& spec = specs_[k];
    if (spec.flag.name.empty()) continue;
    std::string help = spec.doc;
    if (!spec.unit.empty()) help += " [" + spec.unit + "]";
    if (spec.flag.sets) {
      command.add_flag(spec.flag.name, switched_[k],
                       help + " (the scene's " + spec.key + " = " + value_text(*spec.flag.sets) + ")");
      continue;
    }
    CLI::Option* option =
        command.add_option(spec.flag.name, texts_[k],
                           help + " (the scene's " + spec.key + "; default " + spec.default_text + ")");
    // Typed at parsing, as a scene's TOML is: a wrong type is a usage error of the flag.
    if (spec.kind == SettingKind::number) option->check(CLI::Number);
    if (spec.kind == SettingKind::integer) option->check(CLI::TypeValidator<std::int64_t>("INTEGER"));
    if (spec.kind == SettingKind::text) option->check(refuse_empty_output_name);  // a text is a file prefix
    // A boolean given a value (a row with a flag but no switch) is read as true or false, nothing else.
    if (spec.kind == SettingKind::boolean) option->check(CLI::IsMember({"true", "false"}));
  }
}

namespace {

std::optional<SettingValue> given_value(const SettingSpec& spec, const std::string& text, bool switched) {
  if (spec.flag.sets) return switched ? spec.flag.sets : std::nullopt;
  if (text.empty()) return std::nullopt;
  switch (spec.kind) {
    case SettingKind::integer: {
      std::int64_t value = 0;
      std::from_chars(text.data(), text.data() + text.size(), value);  // checked by CLI11 already
      return SettingValue(value);
    }
    case SettingKind::number:
      return SettingValue(std::stod(text));
    case SettingKind::boolean:
      return SettingValue(text == "true");
    default:
      return SettingValue(text);
  }
}

}  // namespace

void SettingFlags::insert_into(toml::table& table) const {
  for (std::size_t k = 0; k < specs_.size(); ++k)
    if (const auto value = given_value(specs_[k], texts_[k], switched_[k]))
      std::visit([&](const auto& v) { table.insert_or_assign(specs_[k].key, v); }, *value);
}

std::string SettingFlags::command_text() const {
  std::string text;
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    if (specs_[k].flag.sets ? !switched_[k] : texts_[k].empty()) continue;
    text += " " + specs_[k].flag.name;
    if (!specs_[k].flag.sets) text += " " + texts_[k];
  }
  return text;
}

void SettingFlags::name_flags(const std::string& prefix, FlagNames& names) const {
  for (const SettingSpec& spec : specs_)
    if (!spec.flag.name.empty()) names[prefix + spec.key] = spec.flag.name;
}

}  // namespace contactbench
