// --set key.sub=value overrides, laid into the document before validation.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include "scene/scene_loader.hpp"
#include "scene/scene_sources.hpp"

namespace rollspin::scene {

void applyOverride(toml::table& root, const std::string& arg, std::map<std::string, SourceLoc>& locs) {
  const SourceLoc loc{"--set " + arg};
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    throw badInput(loc, "expected --set key.sub=value (e.g. --set ball.radius=2)");
  const std::string key = arg.substr(0, eq), value = arg.substr(eq + 1);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  // A part may name an entry of an array of tables, counted from 1:
  // segment[2].path.radius (docs/scenes.md#storyboards).
  std::vector<std::size_t> index(parts.size(), 0);  // 0: not an array entry
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::string& p = parts[i];
    const auto open = p.find('[');
    if (open != std::string::npos && i + 1 < parts.size() && p.back() == ']' && open + 2 < p.size()) {
      const std::string digits = p.substr(open + 1, p.size() - open - 2);
      if (digits.size() <= 6 &&
          std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        index[i] = std::stoul(digits);
        if (index[i] == 0) throw badInput(loc, "'{}': entries are counted from 1", p);
        p.resize(open);
      }
    }
    const bool bare = !p.empty() && std::all_of(p.begin(), p.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!bare) throw badInput(loc, "'{}' is not a key path like section.key (or segment[k].key)", key);
  }
  toml::table parsed;
  try {
    parsed = toml::parse(std::string_view("v = " + value), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    // A number TOML cannot hold (1e400) is a number all the same: say so,
    // rather than take it as a word and complain about a string later.
    errno = 0;
    char* end = nullptr;
    std::strtod(value.c_str(), &end);
    if (errno == ERANGE && !value.empty() && end == value.c_str() + value.size())
      throw badInput(loc,
                     "'{}' is out of range: a number here is at most about 1.8e308 in size and, unless 0, at "
                     "least about 2.2e-308",
                     value);
    parsed = toml::table{};
    parsed.insert("v", value);  // a bare word: take it as a string
  }
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* child = t->get(parts[i]);
    if (index[i] > 0) {
      toml::array* entries = child != nullptr ? child->as_array() : nullptr;
      const std::size_t count = entries != nullptr ? entries->size() : 0;
      if (index[i] > count)
        throw badInput(loc, "'{}[{}]': the scene has {} {} entr{}", parts[i], index[i], count, parts[i],
                       count == 1 ? "y" : "ies");
      child = entries->get(index[i] - 1);
    } else if (child == nullptr) {
      t->insert(parts[i], toml::table{});
      child = t->get(parts[i]);
    }
    if (!child->is_table()) throw badInput(loc, "'{}' is not a table, cannot set '{}'", parts[i], key);
    t = child->as_table();
  }
  t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
  locs[key] = loc;
}

void applySetting(toml::table& root, const KeySetting& setting, std::map<std::string, SourceLoc>& locs) {
  toml::node* section = root.get(setting.section);
  if (section == nullptr) {
    root.insert(setting.section, toml::table{});
    section = root.get(setting.section);
  }
  if (!section->is_table())
    throw badInput(setting.from, "'{}' is not a table, cannot set '{}'", setting.section, setting.dottedKey());
  std::visit([&](const auto& v) { section->as_table()->insert_or_assign(setting.key, v); }, setting.value);
  locs[setting.dottedKey()] = setting.from;
}

}  // namespace rollspin::scene
