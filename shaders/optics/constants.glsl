// Constants shared by the optics twins (mirrors std::numbers in src/optics/).
const float PI = 3.14159265358979;
const float HALF_PI = 1.57079632679490;
const float INV_4PI = 0.0795774715459477;  // 1/(4π): the isotropic phase function

// +∞ (IEEE): GLSL has no literal for it and 1.0/0.0 is undefined behaviour.
float positive_infinity() { return uintBitsToFloat(0x7F800000u); }
