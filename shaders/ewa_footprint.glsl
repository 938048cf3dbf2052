// The EWA splat footprint: a line-for-line mirror of src/core/ewa_footprint.cpp.
const float kPi = 3.14159265358979323846;
const float kMinDet = 1e-10;
const float kMinDepthVariance = 1e-4;
const int kFilterEwa = 0;
const int kFilterPlain = 1;
const int kFilterSwan = 2;

struct Projection {
  bool orthographic;
  float focalPixels;
  float pixelsPerUnit;
  vec2 principal;
  vec2 size;
};

struct FootprintParams {
  int filterMode;
  float cutoff;
  float swanSpacing;  // Swan's s: kernel width * smallest spacing
  float cullDepth;
  float lowPass;  // the low-pass filter's variance in pixels^2 of the image drawn into
};

struct Footprint {
  bool visible;
  vec2 center;
  vec3 covariance;  // (a, b, c) of [[a, b], [b, c]]
  vec3 conic;       // the inverse, same layout
  float jacobianDet;
  float peak;
  float radius;
  float depth;
  float stretch;
  vec2 depthSlope;  // depth along the ray through center + dx: depth + dot(depthSlope, dx)
  float depthSigma;
};

float windowIntegral(float c) {
  float e = exp(-0.5 * c);
  float a0 = 2.0 * (1.0 - e);
  float a1 = 4.0 - e * (2.0 * c + 4.0);
  float a2 = 16.0 - e * (2.0 * c * c + 8.0 * c + 16.0);
  return a0 - 2.0 * a1 / c + a2 / (c * c);
}

float windowedGaussian(float r, float cutoff) {
  if (r > cutoff) return 0.0;
  float t = 1.0 - r / cutoff;
  return exp(-0.5 * r) * t * t;
}

mat3 surfaceCovariance(mat3 rotation, vec3 spacing, vec3 n) {
  mat3 p = mat3(1.0) - outerProduct(n, n);
  mat3 v = mat3(vec3(spacing.x * spacing.x, 0, 0), vec3(0, spacing.y * spacing.y, 0),
                vec3(0, 0, spacing.z * spacing.z));
  return rotation * (p * v * p) * transpose(rotation);
}

float surfaceSplatMass(vec3 h, vec3 n, float tauSurface) {
  float layer = max(max(abs(n.x) * h.x, abs(n.y) * h.y), abs(n.z) * h.z);
  return tauSurface * h.x * h.y * h.z / max(layer, 1e-6 * min(min(h.x, h.y), h.z));
}

float erfApprox(float x) {
  float ax = abs(x);
  float p = 1.0 + ax * (0.0705230784 +
                        ax * (0.0422820123 +
                              ax * (0.0092705272 +
                                    ax * (0.0001520143 + ax * (0.0002765672 + ax * 0.0000430638)))));
  p *= p;
  p *= p;
  p *= p;
  p *= p;
  float y = 1.0 - 1.0 / p;
  return x < 0.0 ? -y : y;
}

// erf on [-kErfSeriesReach, kErfSeriesReach] as an odd polynomial (src/core/ewa_footprint.h).
const float kErfSeriesReach = 0.75;
float erfSeries(float x) {
  float x2 = x * x;
  return x * (1.12837876 +
              x2 * (-0.37611182 + x2 * (0.11269018 + x2 * (-0.02624959 + x2 * 0.00407206))));
}

// Set by the splat variant where the profile's cut lies within kErfSeriesReach (the C++ picks
// by the cut itself); a branch on the uniform cut cost llvmpipe both sides (frames 1.1x longer).
#ifndef SPLAT_ERF_SERIES
#define SPLAT_ERF_SERIES 0
#endif

// The depth profile (DepthProfile): x the cut in erf's argument, y 1 / profileErf(x).
// erf of the profile's cumulative at (z - mu) * s: the argument clamped to the cut.
float profileErf(float t, vec2 profile) {
  float x = clamp(t, -profile.x, profile.x);
#if SPLAT_ERF_SERIES
  return erfSeries(x);
#else
  return erfApprox(x);
#endif
}

// Infinite bounds are passed as flags: open tails of the first and last slab of a kernel.
float slabFraction(float mu, float sigma, float zNear, float zFar, bool openNear, bool openFar,
                   vec2 profile) {
  float s = 1.0 / (sqrt(2.0) * sigma);
  float hi = profileErf(openFar ? profile.x : (zFar - mu) * s, profile);
  float lo = profileErf(openNear ? -profile.x : (zNear - mu) * s, profile);
  return 0.5 * profile.y * (hi - lo);
}

// The slab's share split at its middle plane: (front half, back half); they add up to
// slabFraction's, with one erf more.
vec2 slabHalves(float mu, float sigma, float zNear, float zFar, bool openNear, bool openFar,
                vec2 profile) {
  float s = 1.0 / (sqrt(2.0) * sigma);
  float hi = profileErf(openFar ? profile.x : (zFar - mu) * s, profile);
  float mid = profileErf((0.5 * (zNear + zFar) - mu) * s, profile);
  float lo = profileErf(openNear ? -profile.x : (zNear - mu) * s, profile);
  return 0.5 * profile.y * vec2(mid - lo, hi - mid);
}

// The slab's share in four quarters, front to back, inside the depths `kept` (unbounded: the
// whole share); they add up to slabFraction's, with three erf more. Each quarter's bounds are
// clamped to `kept`, so a cut costs no erf more.
vec4 slabQuarters(float mu, float sigma, float zNear, float zFar, bool openNear, bool openFar,
                  vec2 kept, vec2 profile) {
  float s = 1.0 / (sqrt(2.0) * sigma);
  float q = 0.25 * (zFar - zNear);
  vec4 lo = vec4(openNear ? -1e30 : zNear, zNear + q, 0.5 * (zNear + zFar), zFar - q);
  float hi = openFar ? 1e30 : zFar;
  kept.y = max(kept.x, kept.y);  // nothing kept: every bound at one depth, every share 0
  lo = (clamp(lo, kept.x, kept.y) - mu) * s;
  hi = (clamp(hi, kept.x, kept.y) - mu) * s;
  float e0 = profileErf(lo.x, profile), e1 = profileErf(lo.y, profile);
  float e2 = profileErf(lo.z, profile), e3 = profileErf(lo.w, profile);
  float e4 = profileErf(hi, profile);
  return 0.5 * profile.y * max(vec4(e1 - e0, e2 - e1, e3 - e2, e4 - e3), 0.0);
}

// depthProfileMisses (src/core/ewa_footprint.h): no share of the kernel between zNear and zFar
// for any mean depth within mu +- spread.
bool depthProfileMisses(float mu, float spread, float sigma, float zNear, float zFar,
                        vec2 profile) {
  if (!(profile.x < 1e20)) return false;
  float reach = profile.x * sqrt(2.0) * sigma * 1.0001;
  float margin = 1e-5 * (abs(mu) + spread + reach) + 1e-4 * sigma;
  return mu - spread - reach >= zFar + margin || mu + spread + reach <= zNear - margin;
}

bool cullKernel(vec3 u, float radius, Projection proj, FootprintParams params) {
  float depth = -u.z;
  if (depth <= params.cullDepth) return true;
  float hw = proj.size.x * 0.5, hh = proj.size.y * 0.5;
  if (proj.orthographic) {
    float s = proj.pixelsPerUnit;
    return abs(u.x) * s - hw > radius * s || abs(u.y) * s - hh > radius * s;
  }
  float f = proj.focalPixels;
  float nx = inversesqrt(f * f + hw * hw), ny = inversesqrt(f * f + hh * hh);
  return (f * abs(u.x) + hw * u.z) * nx > radius || (f * abs(u.y) + hh * u.z) * ny > radius;
}

Footprint computeFootprint(vec3 u, mat3 covIn, Projection proj, FootprintParams params) {
  Footprint fp;
  fp.visible = false;
  fp.depth = -u.z;
  if (!(fp.depth > params.cullDepth)) return fp;
  float d = fp.depth;
  float ppu = proj.orthographic ? proj.pixelsPerUnit : proj.focalPixels / d;
  fp.stretch = params.filterMode == kFilterSwan ? max(1.0, 1.0 / (ppu * params.swanSpacing)) : 1.0;
  mat3 cov = covIn * (fp.stretch * fp.stretch);
  vec3 j0, j1;
  if (proj.orthographic) {
    j0 = vec3(ppu, 0.0, 0.0);
    j1 = vec3(0.0, ppu, 0.0);
    fp.jacobianDet = ppu * ppu;
    fp.center = proj.principal + u.xy * ppu;
  } else {
    float f = proj.focalPixels;
    j0 = vec3(f / d, 0.0, f * u.x / (d * d));
    j1 = vec3(0.0, f / d, f * u.y / (d * d));
    fp.jacobianDet = f * f * length(u) / (d * d * d);
    fp.center = proj.principal + u.xy * (f / d);
  }
  vec3 c0 = cov * j0, c1 = cov * j1;
  float a = dot(j0, c0), b = dot(j0, c1), c = dot(j1, c1);
  if (params.filterMode == kFilterEwa) {
    a += params.lowPass;
    c += params.lowPass;
  }
  float det = max(a * c - b * b, kMinDet);
  fp.covariance = vec3(a, b, c);
  fp.conic = vec3(c / det, -b / det, a / det);
  fp.peak = fp.jacobianDet / (kPi * sqrt(det) * windowIntegral(params.cutoff));
  float lambdaMax = 0.5 * (a + c) + sqrt(0.25 * (a - c) * (a - c) + b * b);
  fp.radius = sqrt(params.cutoff * lambdaMax);
  vec2 v = vec2(-c0.z, -c1.z);
  fp.depthSlope = vec2(fp.conic.x * v.x + fp.conic.y * v.y, fp.conic.y * v.x + fp.conic.z * v.y);
  float var = cov[2][2] - dot(v, fp.depthSlope);
  fp.depthSigma = sqrt(max(var, kMinDepthVariance * cov[2][2] + 1e-20));
  fp.visible = !isinf(fp.peak) && !isnan(fp.peak) && !isinf(fp.radius) && !isnan(fp.radius);
  return fp;
}

const float kPointSpriteMargin = 0.125;  // src/core/ewa_footprint.h
float pointSpriteSize(Footprint fp, float cutoff) {
  float extent = max(fp.covariance.x, fp.covariance.z);
  return 2.0 * sqrt(cutoff * extent) + kPointSpriteMargin;
}
