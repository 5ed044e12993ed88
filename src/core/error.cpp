#include <airlight/error.hpp>

namespace airlight {

namespace {
std::string describe(const std::string& file, const std::string& key, const std::string& message) {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (!key.empty()) text += ": " + key;
  return text + ": " + message;
}
}  // namespace

InputError::InputError(std::string file, std::string key, const std::string& message)
    : std::runtime_error(describe(file, key, message)), file_(std::move(file)), key_(std::move(key)),
      message_(message) {}

}  // namespace airlight
