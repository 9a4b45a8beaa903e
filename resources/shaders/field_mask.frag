#version 330 core
// Black outside the field stop; alpha 0: in focus, for the depth-of-field pass.
out vec4 fragColor;

void main() {
  fragColor = vec4(0.0);
}
