// Prints a transform DCTL's mean float operations per pixel over float32 RGB triples
// from stdin: adds (incl. subtractions), multiplies, divides, comparisons, min/max/clamp
// (a clamp counts 2), transcendental calls (pow, exp2, log, sqrt). Usage: counter N
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dctl_count.h"
#define float counted
#include DCTL_FILE
#undef float

int main(int argc, char **argv)
{
    if (argc < 2) return 2;
    long n = std::strtol(argv[1], nullptr, 10);
    std::vector<float> px(3 * n);
    if (std::fread(px.data(), sizeof(float), px.size(), stdin) != px.size()) return 3;
    for (long i = 0; i < n; ++i) transform(1, 1, 0, 0, px[3 * i], px[3 * i + 1], px[3 * i + 2]);
    const op_counts &c = dctl_ops;
    double d = static_cast<double>(n);
    std::printf("%.3f %.3f %.3f %.3f %.3f %.3f\n", c.add / d, c.mul / d, c.div / d, c.cmp / d,
                c.minmax / d, c.transcendental / d);
    return 0;
}
