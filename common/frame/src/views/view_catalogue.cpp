// The catalogue of views and their encodings; see view_catalogue.hpp.
#include "t10/view_catalogue.hpp"

#include "reference.hpp"

#include <algorithm>
#include <cmath>

namespace t10 {

namespace {

constexpr std::array<const char*, kViewCount> kNames = {"final",  "hdr",  "luminance", "key", "bloom0",
                                                        "bloom1", "blur", "ev",        "nan"};

// The reference's settings with the chain's white point (extras' fYwhite); the rest the tutorial's.
ref::Settings atWhitePoint(double ywhite) {
    ref::Settings settings;
    settings.whitePoint = ywhite;
    return settings;
}

} // namespace

const char* viewName(View view) { return kNames[static_cast<std::size_t>(view)]; }

std::optional<View> findView(const std::string& name) {
    for (int i = 0; i < kViewCount; ++i) {
        if (name == kNames[static_cast<std::size_t>(i)]) return static_cast<View>(i);
    }
    return std::nullopt;
}

std::string allViewNames() {
    std::string names;
    for (const char* name : kNames) names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

namespace views {

double displayEncode(double linear, double exposure) {
    return std::pow(std::clamp(linear * exposure, 0.0, 1.0), 1.0 / kDisplayGamma);
}

const std::array<Rgb, kScaleStops>& colourScaleStops() {
    static const std::array<Rgb, kScaleStops> stops = {{{0.0, 0.0, 0.25},
                                                        {0.0, 0.0, 1.0},
                                                        {0.0, 1.0, 1.0},
                                                        {0.0, 1.0, 0.0},
                                                        {1.0, 1.0, 0.0},
                                                        {1.0, 0.0, 0.0},
                                                        {1.0, 1.0, 1.0}}};
    return stops;
}

Rgb colourScale(double t) {
    const auto& stops = colourScaleStops();
    const double x = std::clamp(t, 0.0, 1.0) * (kScaleStops - 1);
    const int i = std::min(static_cast<int>(x), kScaleStops - 2);
    const double f = x - i;
    Rgb colour{};
    for (int c = 0; c < 3; ++c) colour[c] = stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f;
    return colour;
}

double rangeMap(double y, double ywhite) { return ref::rangeMappedLogLuminance(y, atWhitePoint(ywhite)); }

double keyFromMapped(double mapped, double ywhite) { return ref::keyFromMapped(mapped, atWhitePoint(ywhite)); }

double middleGrey(double key) { return ref::middleGrey(key); }

EvClass classifyEv(double y, double key, double ywhite) {
    const ref::Settings settings = atWhitePoint(ywhite);
    const double yr = ref::middleGrey(key, settings) / key * y;
    if (yr >= ywhite) return {EvKind::Burnt, kEvHighest};
    const double displayed = ref::toneMapLuminance(y, key, settings); // 0 for y <= 0 or NaN: black
    if (!(displayed >= 0.5 / 255.0)) return {EvKind::Black, kEvLowest};
    const int stop = std::clamp(static_cast<int>(std::floor(std::log2(y / key))), kEvLowest, kEvHighest);
    return {displayed > y ? EvKind::Lifted : EvKind::Compressed, stop};
}

Rgb evColour(const EvClass& ev) {
    if (ev.kind == EvKind::Burnt) return {1.0, 1.0, 1.0};
    if (ev.kind == EvKind::Black) return {0.0, 0.0, 0.0};
    Rgb colour = colourScale(static_cast<double>(ev.stop - kEvLowest) / (kEvHighest - kEvLowest) * kEvScaleTop);
    if (ev.kind == EvKind::Compressed) {
        for (double& c : colour) c *= 0.5;
    }
    return colour;
}

int legendHeight(int height) { return std::max(2, height / 20); }

} // namespace views

} // namespace t10
