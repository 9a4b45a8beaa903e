#version 330 core
// Two-light Blinn–Phong, two-sided so the lumen of a cut vessel is lit from inside.
in vec3 eyePosition;
in vec3 eyeNormal;

uniform vec3 baseColor;

out vec4 fragColor;

vec3 light(vec3 n, vec3 v, vec3 dir, vec3 color) {
  vec3 l = normalize(dir);
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) : 0.0;
  return color * (diffuse * baseColor + 0.35 * specular);
}

void main() {
  vec3 n = normalize(eyeNormal);
  vec3 v = normalize(-eyePosition);
  if (dot(n, v) < 0.0) n = -n;
  vec3 c = 0.18 * baseColor;
  c += light(n, v, vec3(0.4, 0.8, 1.0), vec3(0.9));
  c += light(n, v, vec3(-0.7, -0.2, 0.5), vec3(0.35, 0.38, 0.45));
  fragColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
