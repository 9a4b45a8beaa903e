#version 330 core
// Two-light Blinn–Phong, two-sided: a surface seen from behind (the lumen through a cut end,
// the inside of a jaw) is lit with its normal turned toward the eye and drawn darker.
// Depth cues of the microscope: contrast and saturation fall off away from the focal plane
// (its depth of field), and what lies beyond it darkens toward the background.
in vec3 eyePosition;
in vec3 eyeNormal;
in vec3 vertexColour;

uniform bool flatMode;       // shadows: one colour, no lighting
uniform vec4 flatColour;
uniform float specularStrength;
uniform float shininess;
uniform float focusDepth;    // mm from the eye
uniform float depthOfField;  // mm: half-width of the sharp band
uniform float fogStart;      // mm from the eye
uniform float fogEnd;
uniform vec3 fogColour;

out vec4 fragColor;

vec3 light(vec3 n, vec3 v, vec3 dir, vec3 colour, vec3 base) {
  vec3 l = normalize(dir);
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
  return colour * (diffuse * base + specularStrength * specular);
}

void main() {
  if (flatMode) {
    fragColor = flatColour;
    return;
  }
  vec3 n = normalize(eyeNormal);
  vec3 v = normalize(-eyePosition);
  vec3 base = vertexColour;
  if (dot(n, v) < 0.0) {
    n = -n;
    base *= 0.7;
  }
  vec3 c = 0.2 * base;
  c += light(n, v, vec3(0.3, 0.6, 1.0), vec3(0.95), base);
  c += light(n, v, vec3(-0.7, -0.3, 0.6), vec3(0.3, 0.32, 0.38), base);

  float depth = -eyePosition.z;
  float blur = clamp(abs(depth - focusDepth) / depthOfField - 1.0, 0.0, 1.0);
  float grey = dot(c, vec3(0.299, 0.587, 0.114));
  c = mix(c, vec3(grey) * 0.8 + 0.2 * fogColour, 0.6 * blur);
  float fog = clamp((depth - fogStart) / max(fogEnd - fogStart, 1e-3), 0.0, 1.0);
  c = mix(c, fogColour, 0.7 * fog);
  fragColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
