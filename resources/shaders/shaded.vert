#version 330 core
// Per-vertex normals and colours, transformed to eye space for the fragment shader; the
// tissue's surface point and layer (render/tissue_surface.h) pass through unchanged.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;   // a constant (glVertexAttrib) when no colour array is bound
layout(location = 3) in vec4 surface;  // tissue: xyz its rest point in the vessel's frame (mm), w its layer

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;  // of view * model

out vec3 eyePosition;
out vec3 eyeNormal;
out vec3 vertexColour;
out vec4 surfacePoint;

void main() {
  vec4 p = view * (model * vec4(position, 1.0));
  eyePosition = p.xyz;
  eyeNormal = normalMatrix * normal;
  vertexColour = colour;
  surfacePoint = surface;
  gl_Position = projection * p;
}
