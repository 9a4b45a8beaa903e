#version 330 core
// Per-vertex normals and colours, transformed to eye space for the fragment shader.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;  // a constant (glVertexAttrib) when no colour array is bound

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;  // of view * model

out vec3 eyePosition;
out vec3 eyeNormal;
out vec3 vertexColour;

void main() {
  vec4 p = view * (model * vec4(position, 1.0));
  eyePosition = p.xyz;
  eyeNormal = normalMatrix * normal;
  vertexColour = colour;
  gl_Position = projection * p;
}
