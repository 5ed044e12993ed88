#pragma once
// The reference's frames cached on disk (issue 6): rendering the reference is
// the slow part of every comparison, so compare, bench and the tests (README
// "Tests and their budget") keep its output in a directory, keyed by a hash of
// everything it depends on — the scene's content (meshes, lights with their
// gobos' texels, media, camera, light model), the size and the reference's
// accuracy settings — so that a changed scene or setting can never reuse a
// stale image.
#include "reference/reference.hpp"

#include <airlight/image.hpp>
#include <airlight/scene.hpp>
#include <filesystem>
#include <string>

namespace airlight::reference {

// $AIRLIGHT_CACHE, else $XDG_CACHE_HOME/airlight, else ~/.cache/airlight.
std::filesystem::path default_cache_dir();

// 16 hex digits: a 64-bit hash of the scene's content, the size and the
// reference's accuracy settings.
std::string reference_key(const Scene& scene, int width, int height, const Settings& settings = {});

struct CachedReference {
  Image airlight, surface;
  double seconds = 0.0;  // the reference's render time when it was made
  bool cached = false;   // read from the cache rather than rendered now
};

// The reference's airlight and surface passes for the scene at that size, from
// `cache_dir` when present, else rendered and stored there: one file,
// <reference_key>.ref, renamed into place whole, so that processes sharing the
// directory never read half an entry. An entry that fails its size or checksum
// check is reported by warn() and rendered again. Throws Failure when the
// directory cannot be written.
CachedReference cached_reference(const Scene& scene, int width, int height, const std::filesystem::path& cache_dir,
                                 const Settings& settings = {});

}  // namespace airlight::reference
