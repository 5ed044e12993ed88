#!/usr/bin/env bash
# The reference cache's read and checksum cost (docs/decisions.md "Interrupted
# runs and the reference cache"): renders a 256x192 reference into a fresh
# cache, then times, best of 20, reading its entry (at once by its size, as
# reference/cache.cpp does, and through a stringstream) and its 64-bit FNV-1a,
# byte by byte as cache.cpp computes it, compiled at -O3.
# usage: bench/cache_checksum.sh   (builds first)
source "$(dirname "$0")/prologue.sh"
build_airlight
$airlight compare --builtin biri_media --methods raymarch --size 256x192 \
  --cache "$work/cache" --out "$work/sheet.png" 2>/dev/null
cat >"$work/time.cpp" <<'CPP'
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }
int main(int, char** argv) {
  double sized = 1e9, streamed = 1e9, hashed = 1e9;
  std::uint64_t h = 0;
  size_t bytes = 0;
  for (int run = 0; run < 20; ++run) {
    const auto t0 = Clock::now();
    std::ifstream in(argv[1], std::ios::binary | std::ios::ate);
    std::string s(static_cast<size_t>(in.tellg()), '\0');
    in.seekg(0);
    in.read(s.data(), static_cast<std::streamsize>(s.size()));
    const auto t1 = Clock::now();
    std::stringstream text;
    text << std::ifstream(argv[1], std::ios::binary).rdbuf();
    const std::string t = text.str();
    const auto t2 = Clock::now();
    h = 0xcbf29ce484222325ull;
    for (const unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
    const auto t3 = Clock::now();
    sized = std::min(sized, ms(t0, t1)), streamed = std::min(streamed, ms(t1, t2)), hashed = std::min(hashed, ms(t2, t3));
    if (t != s) return 1;
    bytes = s.size();
  }
  std::printf("%zu bytes: read by size %.2f ms, through a stringstream %.2f ms; FNV-1a %.2f ms (%016llx)\n", bytes,
              sized, streamed, hashed, static_cast<unsigned long long>(h));
}
CPP
g++ -O3 -std=c++20 "$work/time.cpp" -o "$work/time"
"$work/time" "$work"/cache/*.ref
