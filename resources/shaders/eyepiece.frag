#version 330 core
// The eyepiece pass (render/eyepiece_pass.h): the microscope's depth of field on the lit
// picture (which already shows the field stop: shaded.frag). Each pixel's alpha says how far
// out of focus it lies (0 sharp .. 1, from the lit pass); a pixel is the mean of a disc of taps
// of radius alpha · maxBlur pixels, each tap counted as far as its own blur reaches back to
// the pixel (a sharp object does not smear over a blurred one behind it). TAP_STEP 2 (a
// software rasteriser's variant) takes every other tap of the disc: half the cost.
#ifndef TAP_STEP
#define TAP_STEP 1
#endif
uniform sampler2D picture;  // the lit pass, pixel for pixel with this pass's target
uniform ivec4 area;         // the eye's area in pixels: x, y (GL: from the bottom), width, height
uniform float maxBlur;      // pixels: the blur radius of a fully out-of-focus pixel; 0: no blur

out vec4 fragColor;

// a Poisson disc of 12 taps in the unit circle
const vec2 kTaps[12] = vec2[](vec2(-0.326, -0.406), vec2(-0.840, -0.074), vec2(-0.696, 0.457),
                              vec2(-0.203, 0.621), vec2(0.962, -0.195), vec2(0.473, -0.480),
                              vec2(0.519, 0.767), vec2(0.185, -0.893), vec2(0.507, 0.064),
                              vec2(0.896, 0.412), vec2(-0.322, -0.933), vec2(-0.792, -0.598));

vec4 fetch(ivec2 p) {
  return texelFetch(picture, clamp(p, area.xy, area.xy + area.zw - 1), 0);
}

void main() {
  ivec2 here = ivec2(gl_FragCoord.xy);
  vec4 centre = fetch(here);
  vec3 c = centre.rgb;
  float radius = centre.a * maxBlur;
  if (radius >= 0.75) {
    vec3 sum = c;
    float weight = 1.0;
    for (int i = 0; i < 12; i += TAP_STEP) {
      vec2 offset = kTaps[i] * radius;
      vec4 tap = fetch(here + ivec2(round(offset)));
      float reach = clamp(tap.a * maxBlur - length(offset) + 1.0, 0.0, 1.0);
      sum += tap.rgb * reach;
      weight += reach;
    }
    c = sum / weight;
  }
  fragColor = vec4(c, 1.0);
}
