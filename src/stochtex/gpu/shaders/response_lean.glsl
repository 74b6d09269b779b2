// Response: LEAN mapping of the pattern's normal map (paper §6.5),
// LeanResponse on the CPU: the kernel's anisotropic Beckmann lobe of the
// slope statistics (kernel/lean.glsl) lit by a directional light. The
// statistics are those of the slope pair (GpuPattern uploads its pyramids).
// Without uLeanCovariance (the "no covariance" variant) ĉov is 0, as on the
// CPU; uPattern.hasCovariance is then 0 too, so C_l is not fetched.
#include "stochtex/kernel/lean.glsl"
uniform vec3 uLeanLight;    // unit, towards the light (texture frame; the scene's own: gLightDirection)
uniform vec4 uLeanView;     // xyz: a fixed unit direction to the eye; w = 0: the camera's (gEyeDirection)
uniform vec3 uLeanAlbedo;   // linear
uniform float uLeanRoughness, uLeanSpecular;
uniform bool uLeanCovariance;

// The radiance of a lobe under the shading uniforms: the fixed eye of
// uLeanView or the camera's, the scene's light or uLeanLight.
vec3 leanRadiance(LeanLobe lobe) {
    vec3 eye = uLeanView.w != 0.0 ? uLeanView.xyz : gEyeDirection;
    vec3 light = gLightDirection.w != 0.0 ? gLightDirection.xyz : uLeanLight;
    return leanShade(lobe, light, eye, uLeanAlbedo, uLeanSpecular);
}

// The lobe of a footprint whose slopes have these statistics (mean,
// variances, covariance): the kernel's leanLobe with the base roughness,
// ĉov dropped in the variant without covariance. The one place the lobe is
// built: the response below and the export's stochtex_lean_lobe call it.
LeanLobe footprintLobe(vec2 mean, vec2 var, float cov) {
    return leanLobe(mean, var, uLeanCovariance ? cov : 0.0, uLeanRoughness);
}

vec3 footprintResponse(vec2 mean, vec2 var, float cov) { return leanRadiance(footprintLobe(mean, var, cov)); }

// Unfiltered: the base lobe around the point's own slope, a footprint of
// zero variance (LeanResponse::point).
vec3 pointResponse(vec2 slope) { return leanRadiance(footprintLobe(slope, vec2(0.0), 0.0)); }
