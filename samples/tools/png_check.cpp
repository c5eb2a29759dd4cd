// pf_png_check — checks that an image exists, decodes, has the expected size (optional) and is
// not a single flat colour: the samples' smoke tests run it on the screenshots they write.
//
// usage: pf_png_check IMAGE [WIDTHxHEIGHT]
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

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

int main(int argc, char** argv) {
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
