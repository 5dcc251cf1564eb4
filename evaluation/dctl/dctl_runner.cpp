// Runs a transform DCTL (included as DCTL_FILE) over float32 RGB triples: stdin -> stdout.
// Usage: runner N [threshold=T] [limit=L] [invert=0|1]   (the controls the DCTL declares)
// With the single argument "sliders" it prints the sliders' declarations; "time N K"
// reads N pixels, runs the transform over them K times and prints the fastest pass in
// seconds (the output is not written).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "dctl_host.h"
#include DCTL_FILE

int main(int argc, char **argv)
{
#ifdef DCTL_KNOBS
    if (argc == 2 && std::strcmp(argv[1], "sliders") == 0) {
        const dctl_slider *s[2] = {&ocio_thinfilm_threshold_ui, &ocio_thinfilm_limit_ui};
        for (const dctl_slider *u : s)
            std::printf("%s %.9g %.9g %.9g %.9g\n", u->label, u->def, u->lo, u->hi, u->step);
        return 0;
    }
#endif
    for (int i = 3; i <= argc; ++i) {
        const char *arg = argv[i - 1];
        if (std::strncmp(arg, "invert=", 7) == 0) ocio_thinfilm_invert = std::atoi(arg + 7);
#ifdef DCTL_KNOBS
        if (std::strncmp(arg, "threshold=", 10) == 0) ocio_thinfilm_threshold = std::strtof(arg + 10, nullptr);
        if (std::strncmp(arg, "limit=", 6) == 0) ocio_thinfilm_limit = std::strtof(arg + 6, nullptr);
#endif
    }
    if (argc == 4 && std::strcmp(argv[1], "time") == 0) {
        long n = std::strtol(argv[2], nullptr, 10), k = std::strtol(argv[3], nullptr, 10);
        std::vector<float> px(3 * n), out(3 * n);
        if (std::fread(px.data(), sizeof(float), px.size(), stdin) != px.size()) return 3;
        double best = 1e30;
        for (long r = 0; r < k; ++r) {
            auto t0 = std::chrono::steady_clock::now();
            for (long i = 0; i < n; ++i) {
                float3 o = transform(1, 1, 0, 0, px[3 * i], px[3 * i + 1], px[3 * i + 2]);
                out[3 * i] = o.x;
                out[3 * i + 1] = o.y;
                out[3 * i + 2] = o.z;
            }
            std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
            best = dt.count() < best ? dt.count() : best;
        }
        double sum = 0.0;  // keeps the work observable
        for (float v : out) sum += v;
        std::printf("%.9g %.9g\n", best, sum);
        return 0;
    }
    if (argc < 2) return 2;
    long n = std::strtol(argv[1], nullptr, 10);
    std::vector<float> px(3 * n);
    if (std::fread(px.data(), sizeof(float), px.size(), stdin) != px.size()) return 3;
    for (long i = 0; i < n; ++i) {
        float3 o = transform(1, 1, 0, 0, px[3 * i], px[3 * i + 1], px[3 * i + 2]);
        px[3 * i] = o.x;
        px[3 * i + 1] = o.y;
        px[3 * i + 2] = o.z;
    }
    if (std::fwrite(px.data(), sizeof(float), px.size(), stdout) != px.size()) return 4;
    return std::fflush(stdout) == 0 ? 0 : 5;
}
