#version 330 core
// Per-vertex normals, transformed to eye space for the fragment shader's lighting.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 modelView;
uniform mat4 projection;
uniform mat3 normalMatrix;

out vec3 eyePosition;
out vec3 eyeNormal;

void main() {
  vec4 p = modelView * vec4(position, 1.0);
  eyePosition = p.xyz;
  eyeNormal = normalMatrix * normal;
  gl_Position = projection * p;
}
