// A small host for DaVinci Resolve transform DCTLs in plain C++ (for tests and benchmarks
// where no Resolve is installed): DCTL's documented types, qualifiers and math built-ins
// mapped onto <cmath> in single precision, and DEFINE_UI_PARAMS as a global float a test
// can set. Only what the exported shaders use is mapped; a DCTL that uses anything else
// fails to compile here, which is the point.
#pragma once
#include <cmath>

struct float3 {
    float x, y, z;
};
static inline float3 make_float3(float x, float y, float z) { return float3{x, y, z}; }

#define __DEVICE__ static inline
#define __CONSTANT__ static const
#define __CONSTANTREF__ const

static inline float _fabs(float x) { return std::fabs(x); }
static inline float _powf(float x, float y) { return std::pow(x, y); }
static inline float _logf(float x) { return std::log(x); }
static inline float _log2f(float x) { return std::log2(x); }
static inline float _expf(float x) { return std::exp(x); }
static inline float _exp2f(float x) { return std::exp2(x); }
static inline float _sqrtf(float x) { return std::sqrt(x); }
static inline float _fmaxf(float x, float y) { return std::fmax(x, y); }
static inline float _fminf(float x, float y) { return std::fmin(x, y); }
static inline float _clampf(float x, float lo, float hi) { return std::fmin(std::fmax(x, lo), hi); }
static inline float _saturatef(float x) { return std::fmin(std::fmax(x, 0.0f), 1.0f); }

// DEFINE_UI_PARAMS(variable, label, type, ...): a global holding the control's default,
// which a test can set; a slider's range is kept so a test can check its declaration.
// The float slider and the check box are mapped (what the exported shaders use).
struct dctl_slider {
    const char *label;
    float def, lo, hi, step;
};
#define DCTL_UI_DCTLUI_SLIDER_FLOAT(name, label, def, lo, hi, step)                      \
    static float name = (def);                                                           \
    static const dctl_slider name##_ui = {#label, (def), (lo), (hi), (step)};
#define DCTL_UI_DCTLUI_CHECK_BOX(name, label, def)                                       \
    static int name = (def);                                                             \
    static const char *name##_label = #label;
#define DEFINE_UI_PARAMS(name, label, type, ...) DCTL_UI_##type(name, label, __VA_ARGS__)
