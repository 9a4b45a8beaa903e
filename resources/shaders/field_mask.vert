#version 330 core
// The field stop's mask (render/eyepiece_pass.h): triangles in normalised device coordinates on
// the near plane, so that everything drawn after them where they lie fails the depth test.
layout(location = 0) in vec2 position;

void main() {
  gl_Position = vec4(position, -1.0, 1.0);
}
