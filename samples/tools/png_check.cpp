// pf_png_check — checks that an image exists, decodes, has the expected size (optional) and is
// not a single flat colour: the samples' smoke tests run it on the screenshots they write.
// With --differs it compares two images of the same view at given pixels instead: something
// drawn in the first and not in the second must show there (the obstacle drawing test).
//
// usage: pf_png_check IMAGE [WIDTHxHEIGHT]
//        pf_png_check --differs IMAGE OTHER X,Y [X,Y ...]   (pixels, origin top-left)
// Exit status 0 when the image passes; otherwise 1 with the reason on stderr.

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>

namespace {

// Mean colour of the 3x3 pixels around (x, y), clamped to the image.
void mean_colour(const unsigned char* px, int w, int h, int x, int y, double out[3]) {
    out[0] = out[1] = out[2] = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int cx = std::min(std::max(x + dx, 0), w - 1), cy = std::min(std::max(y + dy, 0), h - 1);
            const unsigned char* p = px + 3 * (size_t(cy) * size_t(w) + size_t(cx));
            for (int c = 0; c < 3; ++c) out[c] += p[c] / 9.0;
        }
}

// A difference the eye sees at once: 40 of 765 summed over R, G and B (about 5%), far above
// the renderers' run-to-run noise (none: the same frame is drawn) and dithering.
constexpr double kMinDifference = 40.0;

int check_differs(int argc, char** argv) {
    int w = 0, h = 0, n = 0, w2 = 0, h2 = 0;
    unsigned char* a = stbi_load(argv[2], &w, &h, &n, 3);
    unsigned char* b = stbi_load(argv[3], &w2, &h2, &n, 3);
    int rc = 0;
    if (!a || !b) {
        std::fprintf(stderr, "pf_png_check: cannot read %s: %s\n", a ? argv[3] : argv[2], stbi_failure_reason());
        rc = 1;
    } else if (w != w2 || h != h2) {
        std::fprintf(stderr, "pf_png_check: %s is %dx%d, %s is %dx%d\n", argv[2], w, h, argv[3], w2, h2);
        rc = 1;
    }
    for (int i = 4; rc == 0 && i < argc; ++i) {
        double fx = 0, fy = 0;
        if (std::sscanf(argv[i], "%lf,%lf", &fx, &fy) != 2 || fx < 0 || fy < 0 || fx >= w || fy >= h) {
            std::fprintf(stderr, "pf_png_check: %s: not a pixel X,Y inside %dx%d\n", argv[i], w, h);
            rc = 1;
            break;
        }
        const int x = int(std::lround(fx)), y = int(std::lround(fy));
        double ca[3], cb[3];
        mean_colour(a, w, h, x, y, ca);
        mean_colour(b, w, h, x, y, cb);
        const double diff = std::fabs(ca[0] - cb[0]) + std::fabs(ca[1] - cb[1]) + std::fabs(ca[2] - cb[2]);
        std::printf("pixel %d,%d: %.0f %.0f %.0f vs %.0f %.0f %.0f, difference %.1f (at least %.0f)\n", x, y, ca[0],
                    ca[1], ca[2], cb[0], cb[1], cb[2], diff, kMinDifference);
        if (diff < kMinDifference) {
            std::fprintf(stderr, "pf_png_check: %s and %s look alike at pixel %d,%d\n", argv[2], argv[3], x, y);
            rc = 1;
        }
    }
    if (a) stbi_image_free(a);
    if (b) stbi_image_free(b);
    return rc;
}

} // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "--differs") == 0) {
        if (argc < 5) {
            std::fprintf(stderr, "usage: pf_png_check --differs IMAGE OTHER X,Y [X,Y ...]\n");
            return 2;
        }
        return check_differs(argc, argv);
    }
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: pf_png_check IMAGE [WIDTHxHEIGHT]\n");
        return 2;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px) {
        std::fprintf(stderr, "pf_png_check: %s: cannot read: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    int rc = 0;
    if (argc == 3) {
        int ew = 0, eh = 0;
        if (std::sscanf(argv[2], "%dx%d", &ew, &eh) != 2 || ew != w || eh != h) {
            std::fprintf(stderr, "pf_png_check: %s: %dx%d, expected %s\n", argv[1], w, h, argv[2]);
            rc = 1;
        }
    }
    // Distinct colours (quantised to 5 bits per channel) and the luminance spread.
    std::set<int> colours;
    double sum = 0, sum2 = 0;
    const size_t count = size_t(w) * size_t(h);
    for (size_t i = 0; i < count; ++i) {
        const unsigned char* p = px + 3 * i;
        colours.insert((p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3));
        const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        sum += y;
        sum2 += y * y;
    }
    const double mean = sum / double(count);
    const double sd = std::sqrt(std::max(0.0, sum2 / double(count) - mean * mean));
    std::printf("%s: %dx%d, %zu distinct colours, luminance mean %.1f sd %.1f\n", argv[1], w, h, colours.size(), mean,
                sd);
    if (colours.size() < 16 || sd < 2.0) {
        std::fprintf(stderr, "pf_png_check: %s looks uniform\n", argv[1]);
        rc = 1;
    }
    stbi_image_free(px);
    return rc;
}
