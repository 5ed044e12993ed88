// Every covered pixel white: one fragment shader invocation per pixel.
out vec4 color;
void main() { color = vec4(1.0); }
