#pragma once
// Phase functions (docs/design.md §1), each normalized to integrate to 1 over the sphere.
// cos_theta is the cosine between the light's direction of travel and the
// direction toward the eye, so g > 0 scatters forward.
#include <airlight/scene.hpp>

namespace airlight::optics {

// Schlick's k for a Henyey–Greenstein g (Kingston eq. 16), kept inside |k| < 1.
double schlick_k(double g);
double phase(const PhaseLobe& lobe, double cos_theta);
double phase(const Phase& phase, double cos_theta);

}  // namespace airlight::optics
