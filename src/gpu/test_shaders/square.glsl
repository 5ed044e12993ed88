// Included twice by fill.comp.glsl: the second include must be skipped.
float square(float x) { return x * x; }
