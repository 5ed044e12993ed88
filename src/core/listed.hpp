#pragma once
// Items as a message lists them: "a", "a and b", "a, b and c" (or "or").
#include <string>
#include <vector>

namespace airlight {

inline std::string listed(const std::vector<std::string>& items, const std::string& conjunction = "and") {
  std::string text;
  for (size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " " + conjunction + " " : ", ") + items[i];
  return text;
}

}  // namespace airlight
