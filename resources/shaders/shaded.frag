#version 330 core
// Two-light Blinn–Phong, two-sided: a surface seen from behind (the inside of a jaw) is lit
// with its normal turned toward the eye and drawn darker.
//
// Tissue (compiled with TISSUE_WALL, render/tissue_surface.h) is shaded as living wall rather than
// plastic: a procedural texture on the vertex's rest point in its vessel's frame (so it stays
// on the wall as the wall moves, and has no seam round it) — fine grain, faint fibres along
// the outer wall and round the lumen, the small dark-red vessels of the wall's own supply
// (vasa vasorum) on the outer wall — wrap lighting with a red scatter at the terminator (light
// that enters the wall and leaves it redder), and a small, sharp, moist highlight. The cut face
// is shaded flat (its own face's normal: the wall's thickness reads as an edge) and the lumen
// keeps the occlusion baked into its colour.
//
// Depth cues of the microscope: contrast and saturation fall off away from the focal plane,
// and what lies beyond it darkens toward the background. The eyepiece's field stop is applied
// here, per fragment (free, where a pass of its own would cost a software rasteriser a good part of
// its frame rate). With `focusInAlpha` the output's
// alpha is how far out of focus the fragment is (0 sharp .. 1), for the eyepiece pass's blur
// (render/eyepiece_pass.h); otherwise it is 1.
in vec3 eyePosition;
in vec3 eyeNormal;
in vec3 vertexColour;
in vec4 surfacePoint;

uniform bool flatMode;       // shadows: one colour, no lighting
uniform vec4 flatColour;
uniform float specularStrength;
uniform float shininess;
uniform float focusDepth;    // mm from the eye
uniform float depthOfField;  // mm: half-width of the sharp band
uniform float fogStart;      // mm from the eye
uniform float fogEnd;
uniform vec3 fogColour;
uniform bool focusInAlpha;   // alpha = out-of-focus amount (the eyepiece pass blurs by it)
uniform bool sharp;          // marks: always in focus
uniform vec4 fieldStop;      // the eyepiece's circular field: centre (px, GL's frame), radius, soft edge (px); radius 0: none

out vec4 fragColor;

const vec3 kKeyLight = vec3(0.3, 0.6, 1.0);
const vec3 kFillLight = vec3(-0.7, -0.3, 0.6);
const vec3 kVasaColour = vec3(0.36, 0.03, 0.06);

vec3 light(vec3 n, vec3 v, vec3 dir, vec3 colour, vec3 base) {
  vec3 l = normalize(dir);
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
  return colour * (diffuse * base + specularStrength * specular);
}

#ifdef TISSUE_WALL
// value noise in [0, 1] on a unit lattice in the plane (hash of the corners, smooth
// interpolation): four hashes a sample, cheap enough for a software rasteriser
float hash(vec2 p) {
  p = fract(p * vec2(0.3183099, 0.3678794) + vec2(0.71, 0.113));
  p *= 17.0;
  return fract(p.x * p.y * (p.x + p.y));
}

float noise(vec2 x) {
  vec2 i = floor(x);
  vec2 f = fract(x);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1, 0)), f.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), f.x), f.y);
}

// the wall's colour at rest point p (mm, vessel frame: x along the axis) of `layer`, from
// the wall unrolled: along the axis, and round it (the seam, where the angle wraps, lies on
// the vessel's underside)
vec3 wallTexture(vec3 p, float layer, vec3 base) {
  float radius = length(p.yz);
  vec2 wall = vec2(p.x, atan(p.z, p.y) * max(radius, 0.05));  // mm
  float grain = noise(wall * 55.0);
  // outer wall: longitudinal collagen; lumen: circumferential folds of the intima; cut face:
  // the wall's layers in section, concentric lamellae
  float outer = 1.0 - step(0.5, layer);
  float cut = step(1.5, layer);
  vec2 stripes = mix(vec2(wall.x * 40.0, wall.y * 3.0), vec2(wall.x * 5.0, wall.y * 70.0), outer);
  stripes = mix(stripes, vec2(radius * 160.0, wall.y * 6.0), cut);
  float fibres = noise(stripes);
  vec3 c = base * (0.86 + 0.14 * grain + 0.10 * fibres);
  // the vasa vasorum on the outer wall: thin dark-red lines where a warped ridge of noise
  // peaks, branching at two scales
  vec2 q = wall * 1.3 + 0.25 * sin(wall.yx * 3.1);
  float ridge = 1.0 - abs(2.0 * noise(q) - 1.0);
  float fine = 1.0 - abs(2.0 * noise(q * 2.7 + 1.7) - 1.0);
  float vasa = max(smoothstep(0.955, 0.99, ridge), 0.6 * smoothstep(0.975, 0.995, fine));
  return mix(c, kVasaColour, 0.6 * vasa * outer);
}

// the tissue's light: wrap diffuse, red scatter at the terminator, a moist highlight
vec3 tissueLight(vec3 n, vec3 v, vec3 dir, vec3 colour, vec3 base) {
  vec3 l = normalize(dir);
  float ndl = dot(n, l);
  const float wrap = 0.45;
  float diffuse = max((ndl + wrap) / (1.0 + wrap), 0.0);
  float scatter = max(diffuse - max(ndl, 0.0), 0.0);
  vec3 h = normalize(l + v);
  float specular = ndl > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
  return colour * (diffuse * base + scatter * base * vec3(0.55, 0.12, 0.10) + specularStrength * specular);
}

#endif

// the light the field stop lets through here (render/eyepiece_pass.h): a slight fall-off
// toward the edge, black beyond it; all of it without a stop
float fieldStopLight() {
  if (fieldStop.z <= 0.0) return 1.0;
  float r = length(gl_FragCoord.xy - fieldStop.xy);
  float edge = clamp(r / fieldStop.z, 0.0, 1.0);
  return (1.0 - 0.22 * edge * edge * edge) * (1.0 - smoothstep(fieldStop.z - fieldStop.w, fieldStop.z, r));
}

void main() {
  if (flatMode) {
    fragColor = vec4(flatColour.rgb * fieldStopLight(), flatColour.a);
    return;
  }
  vec3 n = normalize(eyeNormal);
  vec3 v = normalize(-eyePosition);
  vec3 base = vertexColour;
#ifdef TISSUE_WALL
  float layer = surfacePoint.w;
  if (layer > 1.5) n = normalize(cross(dFdx(eyePosition), dFdy(eyePosition)));
  if (dot(n, v) < 0.0) n = -n;
  base = wallTexture(surfacePoint.xyz, layer, base);
  vec3 c = 0.22 * base;
  c += tissueLight(n, v, kKeyLight, vec3(0.95), base);
  c += tissueLight(n, v, kFillLight, vec3(0.3, 0.32, 0.38), base);
#else
  if (dot(n, v) < 0.0) {
    n = -n;
    base *= 0.7;
  }
  vec3 c = 0.2 * base;
  c += light(n, v, kKeyLight, vec3(0.95), base);
  c += light(n, v, kFillLight, vec3(0.3, 0.32, 0.38), base);
#endif

  float depth = -eyePosition.z;
  float blur = sharp ? 0.0 : clamp(abs(depth - focusDepth) / depthOfField - 1.0, 0.0, 1.0);
  float grey = dot(c, vec3(0.299, 0.587, 0.114));
  c = mix(c, vec3(grey) * 0.8 + 0.2 * fogColour, 0.6 * blur);
  float fog = clamp((depth - fogStart) / max(fogEnd - fogStart, 1e-3), 0.0, 1.0);
  c = mix(c, fogColour, 0.7 * fog);
  fragColor = vec4(pow(c, vec3(1.0 / 2.2)) * fieldStopLight(), focusInAlpha ? blur : 1.0);
}
