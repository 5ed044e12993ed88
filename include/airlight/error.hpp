#pragma once
// Errors that reach the user: bad input, naming the file and the key, and any
// other failure (the command exits 2 and 1 for them: docs/design.md §5).
#include <airlight/export.hpp>
#include <stdexcept>
#include <string>

namespace airlight {

// Bad input: a scene file, a mesh, an image, a command-line value.
// what() reads "<file>: <key>: <message>" (the key may be empty).
class AIRLIGHT_API InputError : public std::runtime_error {
public:
  InputError(std::string file, std::string key, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

private:
  std::string file_, key_, message_;
};

// Any other failure: no OpenGL context, an I/O error on output, an internal limit.
class AIRLIGHT_API Failure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The GPU (or, on llvmpipe, the process) ran out of memory: GL_OUT_OF_MEMORY.
class AIRLIGHT_API OutOfMemory : public Failure {
public:
  using Failure::Failure;
};

}  // namespace airlight
