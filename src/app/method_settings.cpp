#include "app/method_settings.hpp"

#include <airlight/error.hpp>

#include <algorithm>

namespace airlight::app {

Settings method_settings(const MethodInfo& method, const std::vector<std::string>& assignments) {
  Settings settings(method.settings);
  for (std::string a : assignments) {
    const auto dot = a.find('.'), eq = a.find('=');
    if (dot != std::string::npos && dot < eq) {
      if (a.substr(0, dot) != method.name)
        throw InputError("--set", a.substr(0, eq), "the setting names another method than '" + method.name + "'");
      a = a.substr(dot + 1);
    }
    settings.set(a, "--set");
  }
  return settings;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t end; (end = text.find(separator, start)) != std::string::npos; start = end + 1)
    parts.push_back(text.substr(start, end - start));
  parts.push_back(text.substr(start));
  return parts;
}

// ---- compare ----

namespace {

// --set takes "method.key=value" only: with several methods a bare key would be
// ambiguous, and a method missing from --methods is most likely a typo.
void check_assignments(const std::vector<std::string>& assignments, const std::string& methods) {
  const std::vector<std::string> names = split(methods, ',');
  for (const auto& a : assignments) {
    const auto dot = a.find('.'), eq = a.find('=');
    const bool named = dot != std::string::npos && dot < eq;
    if (!named) throw InputError("--set", a.substr(0, eq), "name the method: --set method.key=value");
    const std::string method = a.substr(0, dot);
    const bool listed = std::any_of(names.begin(), names.end(),
                                    [&](const std::string& n) { return n.substr(0, n.find(':')) == method; });
    if (!listed) throw InputError("--set", a.substr(0, eq), "the method '" + method + "' is not in --methods");
  }
}

// The --set assignments of the entry's method, then the entry's own settings.
MethodEntry parse_entry(const std::string& text, const std::vector<std::string>& assignments) {
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  if (name.empty() || (colon != std::string::npos && colon + 1 == text.size()))
    throw InputError("--methods", text.empty() ? "(empty entry)" : text, "expected NAME or NAME:key=value;key=value, entries separated by ','");
  MethodEntry entry{&find_method(name, "--methods"), {}};
  std::vector<std::string> own;
  for (const auto& a : assignments)
    if (a.substr(0, a.find('.')) == name) own.push_back(a);
  entry.settings = method_settings(*entry.info, own);
  if (colon != std::string::npos)
    for (const auto& assignment : split(text.substr(colon + 1), ';')) entry.settings.set(assignment, "--methods");
  return entry;
}

}  // namespace

std::vector<MethodEntry> parse_entries(const std::string& methods, const std::vector<std::string>& assignments) {
  check_assignments(assignments, methods);
  std::vector<MethodEntry> entries;
  for (const auto& text : split(methods, ',')) entries.push_back(parse_entry(text, assignments));
  return entries;
}

// ---- bench ----

namespace {

// --sweep method.key=v1,v2,...
struct Sweep {
  std::string method, key;
  std::vector<std::string> values;
};

Sweep parse_sweep(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw InputError("--sweep", text, "expected method.key=v1,v2,...");
  const std::string name = text.substr(0, eq);
  const auto dot = name.find('.');
  if (dot == std::string::npos) throw InputError("--sweep", name, "name the method: method.key=v1,v2,...");
  return {name.substr(0, dot), name.substr(dot + 1), split(text.substr(eq + 1), ',')};
}

std::vector<const MethodInfo*> listed_methods(const std::vector<std::string>& names) {
  std::vector<const MethodInfo*> methods;
  for (const auto& name : names) {
    const MethodInfo& method = find_method(name, "--methods");
    if (std::count(names.begin(), names.end(), name) > 1) throw InputError("--methods", name, "listed twice");
    methods.push_back(&method);
  }
  return methods;
}

// "method.key..." names one of the listed methods; `option` and `key` name it in the error.
void check_listed(const std::string& method, const std::vector<std::string>& listed, const std::string& option,
                  const std::string& key) {
  if (std::find(listed.begin(), listed.end(), method) == listed.end())
    throw InputError(option, key, "method '" + method + "' is not in --methods");
}

// The --set assignments that belong to `method`: "method.key=value", or
// "key=value" when it is the only method.
std::vector<std::string> assignments_for(const std::string& method, const std::vector<std::string>& methods,
                                         const std::vector<std::string>& assignments) {
  std::vector<std::string> own;
  for (const auto& a : assignments) {
    const auto dot = a.find('.'), eq = a.find('=');
    if (dot == std::string::npos || dot > eq) {
      if (methods.size() > 1) throw InputError("--set", a.substr(0, eq), "name the method: method.key=value");
      own.push_back(a);
      continue;
    }
    check_listed(a.substr(0, dot), methods, "--set", a.substr(0, eq));
    if (a.substr(0, dot) == method) own.push_back(a);
  }
  return own;
}

// More runs than anyone times: a few sweeps of a few hundred values each would
// otherwise hold their product in memory before the first run.
constexpr size_t max_runs = 1000;

// A method's runs: its sweeps (in command-line order) form a cross product, the
// first varying slowest; every value is validated here, before anything runs.
std::vector<Variant> method_variants(const MethodInfo& method, const std::vector<Sweep>& sweeps,
                                     const std::vector<std::string>& own_assignments) {
  std::vector<const Sweep*> own;
  size_t runs = 1;
  for (const auto& sweep : sweeps) {
    if (sweep.method != method.name) continue;
    own.push_back(&sweep);
    runs *= sweep.values.size();
    if (runs > max_runs)
      throw InputError("--sweep", method.name + "." + sweep.key,
                       "the sweeps of " + method.name + " make more than " + std::to_string(max_runs) + " runs");
  }
  std::vector<Variant> variants{{&method, method_settings(method, own_assignments), method.name}};
  for (const auto* sweep : own) {
    std::vector<Variant> crossed;
    for (const auto& base : variants)
      for (const auto& value : sweep->values) {
        crossed.push_back(base);
        crossed.back().settings.set(sweep->key, value, "--sweep");
        if (sweep != own.back()) crossed.back().series += " " + sweep->key + "=" + value;
      }
    variants = std::move(crossed);
  }
  return variants;
}

}  // namespace

std::vector<Variant> plan_variants(const std::vector<std::string>& methods, const std::vector<std::string>& sweep_texts,
                                   const std::vector<std::string>& assignments) {
  const auto listed = listed_methods(methods);
  std::vector<Sweep> sweeps;
  for (const auto& text : sweep_texts) {
    sweeps.push_back(parse_sweep(text));
    check_listed(sweeps.back().method, methods, "--sweep", sweeps.back().method + "." + sweeps.back().key);
  }
  std::vector<Variant> planned;
  for (const auto* method : listed) {
    const auto variants = method_variants(*method, sweeps, assignments_for(method->name, methods, assignments));
    planned.insert(planned.end(), variants.begin(), variants.end());
  }
  return planned;
}

}  // namespace airlight::app
