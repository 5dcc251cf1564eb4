// Counts a transform DCTL's float operations per pixel: the DCTL is compiled with
// `float` as `counted`, whose operators and DCTL built-ins add to global counters.
// Include this instead of dctl_host.h and define float as counted around the DCTL.
#pragma once
#include <cmath>

struct op_counts {
    long add, mul, div, cmp, transcendental, minmax;
};
static op_counts dctl_ops = {0, 0, 0, 0, 0, 0};

struct counted {
    float v;
    counted() : v(0.0f) {}
    counted(float x) : v(x) {}
    counted(double x) : v(static_cast<float>(x)) {}
    counted(int x) : v(static_cast<float>(x)) {}
};
static inline counted operator+(counted a, counted b) { ++dctl_ops.add; return a.v + b.v; }
static inline counted operator-(counted a, counted b) { ++dctl_ops.add; return a.v - b.v; }
static inline counted operator-(counted a) { return -a.v; }
static inline counted operator*(counted a, counted b) { ++dctl_ops.mul; return a.v * b.v; }
static inline counted operator/(counted a, counted b) { ++dctl_ops.div; return a.v / b.v; }
static inline bool operator<(counted a, counted b) { ++dctl_ops.cmp; return a.v < b.v; }
static inline bool operator>(counted a, counted b) { ++dctl_ops.cmp; return a.v > b.v; }
static inline bool operator<=(counted a, counted b) { ++dctl_ops.cmp; return a.v <= b.v; }
static inline bool operator>=(counted a, counted b) { ++dctl_ops.cmp; return a.v >= b.v; }
static inline bool operator==(counted a, counted b) { ++dctl_ops.cmp; return a.v == b.v; }

struct float3 {
    counted x, y, z;
};
static inline float3 make_float3(counted x, counted y, counted z) { return float3{x, y, z}; }

#define __DEVICE__ static inline
#define __CONSTANT__ static const
#define __CONSTANTREF__ const

static inline counted _powf(counted x, counted y) { ++dctl_ops.transcendental; return std::pow(x.v, y.v); }
static inline counted _logf(counted x) { ++dctl_ops.transcendental; return std::log(x.v); }
static inline counted _exp2f(counted x) { ++dctl_ops.transcendental; return std::exp2(x.v); }
static inline counted _expf(counted x) { ++dctl_ops.transcendental; return std::exp(x.v); }
static inline counted _log2f(counted x) { ++dctl_ops.transcendental; return std::log2(x.v); }
static inline counted _sqrtf(counted x) { ++dctl_ops.transcendental; return std::sqrt(x.v); }
static inline counted _fmaxf(counted x, counted y) { ++dctl_ops.minmax; return std::fmax(x.v, y.v); }
static inline counted _fminf(counted x, counted y) { ++dctl_ops.minmax; return std::fmin(x.v, y.v); }
static inline counted _saturatef(counted x) { dctl_ops.minmax += 2; return std::fmin(std::fmax(x.v, 0.0f), 1.0f); }

#define DCTL_UI_DCTLUI_SLIDER_FLOAT(name, label, def, lo, hi, step) static counted name = (def);
#define DCTL_UI_DCTLUI_CHECK_BOX(name, label, def) static int name = (def);
#define DEFINE_UI_PARAMS(name, label, type, ...) DCTL_UI_##type(name, label, __VA_ARGS__)
