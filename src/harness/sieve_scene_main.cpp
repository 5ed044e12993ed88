// sieve_scene DIR [TRIANGLES]: writes DIR/sieve.obj and DIR/sieve.json, making DIR
// (harness/sieve_scene.hpp) for scripts/million-triangles; default 10⁶ triangles.
#include "harness/sieve_scene.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: sieve_scene DIR [TRIANGLES]\n");
    return 2;
  }
  const long triangles = argc == 3 ? std::atol(argv[2]) : 1000000L;
  if (triangles <= 0) {
    std::fprintf(stderr, "sieve_scene: TRIANGLES: must be a positive count, got %s\n", argv[2]);
    return 2;
  }
  try {
    std::filesystem::create_directories(argv[1]);
    std::printf("%s\n", airlight::harness::write_sieve_scene(argv[1], triangles).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sieve_scene: %s\n", e.what());
    return 1;
  }
}
