// Type and range checks of the glTF JSON before tinygltf reads it; see gltf_schema.hpp. The rules
// follow the glTF 2.0 schema (object, array, integer >= 0, number and its range, string, enum) for
// the properties gltf_scene.cpp uses, and each index is checked against the array it points into.
#include "t10/gltf_schema.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <type_traits>

namespace t10 {

namespace {

using Json = nlohmann::json;

struct SchemaFault {
    std::string what;
};

// "an object", "a string \"abc\"", "-1": what was found, short enough for one line.
std::string describe(const Json& value) {
    switch (value.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::string: {
        std::string text = value.get<std::string>();
        if (text.size() > 40) text = text.substr(0, 37) + "...";
        return "a string " + Json(text).dump();
    }
    default: return value.dump(); // a number: its value says more than "a number"
    }
}

std::string typeName(const Json& value) {
    if (value.is_number()) return "a number " + value.dump();
    return describe(value);
}

// 0, 1, 1.5708: a bound as a person writes it.
std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

class Checker {
public:
    explicit Checker(const Json& root) : root_(root) {}

    void run() {
        if (!root_.is_object()) fault("the file", "expected a JSON object, got " + typeName(root_));
        // The top-level arrays first: an index into one that is not an array would be misreported.
        for (const char* list : {"scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "materials",
                                 "textures", "samplers", "images", "cameras", "skins", "animations"})
            if (const Json* v = member(root_, list); v != nullptr && !v->is_array())
                fault(list, "expected an array, got " + typeName(*v));
        const Json* asset = member(root_, "asset");
        if (asset == nullptr) fault("asset", "missing (every glTF file has one)");
        object(*asset, "asset");
        if (const Json* v = member(*asset, "version")) string(*v, "asset.version");
        for (const char* list : {"extensionsUsed", "extensionsRequired"})
            forEach(root_, list, [&](const Json& v, const std::string& path) { string(v, path); });
        if (const Json* v = member(root_, "scene")) index(*v, "scene", "scenes");
        forEach(root_, "scenes", [&](const Json& scene, const std::string& path) {
            object(scene, path);
            optional(scene, path, "name", string);
            forEach(scene, "nodes", [&](const Json& v, const std::string& p) { index(v, p, "nodes"); }, path);
        });
        forEach(root_, "nodes", [&](const Json& v, const std::string& path) { node(v, path); });
        forEach(root_, "meshes", [&](const Json& v, const std::string& path) { mesh(v, path); });
        forEach(root_, "accessors", [&](const Json& v, const std::string& path) { accessor(v, path); });
        forEach(root_, "bufferViews", [&](const Json& v, const std::string& path) { bufferView(v, path); });
        forEach(root_, "buffers", [&](const Json& v, const std::string& path) {
            object(v, path);
            required(v, path, "byteLength", [&](const Json& n, const std::string& p) { integer(n, p, 1); });
            optional(v, path, "uri", [&](const Json& n, const std::string& p) { string(n, p); });
        });
        forEach(root_, "materials", [&](const Json& v, const std::string& path) { material(v, path); });
        forEach(root_, "textures", [&](const Json& v, const std::string& path) {
            object(v, path);
            optional(v, path, "source", [&](const Json& n, const std::string& p) { index(n, p, "images"); });
            optional(v, path, "sampler", [&](const Json& n, const std::string& p) { index(n, p, "samplers"); });
        });
        forEach(root_, "samplers", [&](const Json& v, const std::string& path) { sampler(v, path); });
        forEach(root_, "images", [&](const Json& v, const std::string& path) {
            object(v, path);
            optional(v, path, "uri", [&](const Json& n, const std::string& p) { string(n, p); });
            optional(v, path, "mimeType", [&](const Json& n, const std::string& p) { string(n, p); });
            optional(v, path, "bufferView", [&](const Json& n, const std::string& p) { index(n, p, "bufferViews"); });
        });
        forEach(root_, "cameras", [&](const Json& v, const std::string& path) { camera(v, path); });
        forEach(root_, "skins", [&](const Json& v, const std::string& path) { object(v, path); });
        forEach(root_, "animations", [&](const Json& v, const std::string& path) { object(v, path); });
        if (const Json* extensions = member(root_, "extensions")) {
            object(*extensions, "extensions");
            if (const Json* lights = member(*extensions, "KHR_lights_punctual")) {
                object(*lights, "extensions.KHR_lights_punctual");
                forEach(*lights, "lights", [&](const Json& v, const std::string& path) { light(v, path); },
                        "extensions.KHR_lights_punctual");
            }
        }
    }

private:
    // A check borrowed for one call of optional, required or forEach: a lambda (kept by address: it
    // lives until that call returns) or one of the static checks below. std::function did the same at
    // a cost: its machinery, compiled once per lambda (49 here), made this file 12 of the browser
    // build's 84 CPU-seconds.
    class Check {
    public:
        using Function = void (*)(const Json&, const std::string&);
        Check(Function function) : function_(function) {}
        template <typename Lambda, typename = std::enable_if_t<!std::is_function_v<Lambda>>>
        Check(const Lambda& lambda) : lambda_(&lambda), call_(&callLambda<Lambda>) {}
        void operator()(const Json& v, const std::string& path) const {
            if (function_ != nullptr) function_(v, path);
            else call_(lambda_, v, path);
        }

    private:
        template <typename Lambda>
        static void callLambda(const void* lambda, const Json& v, const std::string& path) {
            (*static_cast<const Lambda*>(lambda))(v, path);
        }
        Function function_ = nullptr;
        const void* lambda_ = nullptr;
        void (*call_)(const void*, const Json&, const std::string&) = nullptr;
    };

    [[noreturn]] static void fault(const std::string& path, const std::string& what) {
        throw SchemaFault{path + ": " + what};
    }

    static const Json* member(const Json& object, const char* key) {
        if (!object.is_object()) return nullptr;
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    static std::string join(const std::string& path, const char* key) {
        return path.empty() ? std::string(key) : path + "." + key;
    }

    static void object(const Json& v, const std::string& path) {
        if (!v.is_object()) fault(path, "expected an object, got " + typeName(v));
    }

    static void string(const Json& v, const std::string& path) {
        if (!v.is_string()) fault(path, "expected a string, got " + typeName(v));
    }

    static void boolean(const Json& v, const std::string& path) {
        if (!v.is_boolean()) fault(path, "expected true or false, got " + typeName(v));
    }

    // glTF's integers: a JSON number without a fraction or exponent (tinygltf ignores 1.0 too).
    static std::int64_t integer(const Json& v, const std::string& path, std::int64_t minimum) {
        const std::string wanted = "an integer >= " + std::to_string(minimum);
        if (!v.is_number_integer()) fault(path, "expected " + wanted + ", got " + typeName(v));
        if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
            fault(path, "expected " + wanted + " below 2^31, got " + v.dump());
        const auto i = v.get<std::int64_t>();
        if (i < minimum) fault(path, "expected " + wanted + ", got " + v.dump());
        if (i > std::numeric_limits<std::int32_t>::max()) fault(path, "expected " + wanted + " below 2^31, got " + v.dump());
        return i;
    }

    // An index into the root array `array` (which must hold that element).
    void index(const Json& v, const std::string& path, const char* array) const {
        const std::int64_t i = integer(v, path, 0);
        const Json* list = member(root_, array);
        const std::size_t count = list != nullptr && list->is_array() ? list->size() : 0;
        if (static_cast<std::size_t>(i) >= count)
            fault(path, std::string(array) + "[" + std::to_string(i) + "] does not exist (the file has " +
                            std::to_string(count) + ")");
    }

    // Same, for the lights array of KHR_lights_punctual.
    void lightIndex(const Json& v, const std::string& path) const {
        const std::int64_t i = integer(v, path, 0);
        std::size_t count = 0;
        if (const Json* extensions = member(root_, "extensions"))
            if (const Json* ext = member(*extensions, "KHR_lights_punctual"))
                if (const Json* lights = member(*ext, "lights"); lights != nullptr && lights->is_array())
                    count = lights->size();
        if (static_cast<std::size_t>(i) >= count)
            fault(path, "KHR_lights_punctual light " + std::to_string(i) + " does not exist (the file has " +
                            std::to_string(count) + ")");
    }

    // A number in [lo, hi]; `lowOpen`: lo itself excluded (the schema's exclusiveMinimum).
    static double number(const Json& v, const std::string& path, double lo = -1e300, double hi = 1e300,
                         bool lowOpen = false) {
        if (!v.is_number()) fault(path, "expected a number, got " + typeName(v));
        const double x = v.get<double>();
        const bool below = lowOpen ? !(x > lo) : !(x >= lo);
        if (below || !(x <= hi)) {
            const std::string range = lo <= -1e300  ? "at most " + shortNumber(hi)
                                      : hi >= 1e300 ? (lowOpen ? "above " : "at least ") + shortNumber(lo)
                                                    : "from " + shortNumber(lo) + " to " + shortNumber(hi);
            fault(path, "expected a number " + range + ", got " + v.dump());
        }
        return x;
    }

    static void numbers(const Json& v, const std::string& path, std::size_t count, double lo = -1e300,
                        double hi = 1e300) {
        if (!v.is_array()) fault(path, "expected an array of " + std::to_string(count) + " numbers, got " + typeName(v));
        if (v.size() != count)
            fault(path, "expected " + std::to_string(count) + " numbers, got " + std::to_string(v.size()));
        for (std::size_t i = 0; i < count; ++i) number(v[i], path + "[" + std::to_string(i) + "]", lo, hi);
    }

    static void oneOf(const Json& v, const std::string& path, std::initializer_list<std::int64_t> allowed) {
        std::string list;
        for (const std::int64_t a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
        if (!v.is_number_integer() || std::find(allowed.begin(), allowed.end(), v.get<std::int64_t>()) == allowed.end())
            fault(path, "expected one of " + list + ", got " + typeName(v));
    }

    static void oneOf(const Json& v, const std::string& path, std::initializer_list<const char*> allowed) {
        std::string list;
        for (const char* a : allowed) list += (list.empty() ? "\"" : ", \"") + std::string(a) + "\"";
        bool found = false;
        if (v.is_string())
            for (const char* a : allowed) found = found || v.get<std::string>() == a;
        if (!found) fault(path, "expected one of " + list + ", got " + typeName(v));
    }

    static void optional(const Json& object, const std::string& path, const char* key, const Check& check) {
        if (const Json* v = member(object, key)) check(*v, join(path, key));
    }

    static void required(const Json& object, const std::string& path, const char* key, const Check& check) {
        const Json* v = member(object, key);
        if (v == nullptr) fault(join(path, key), "missing (the schema requires it)");
        check(*v, join(path, key));
    }

    // `key` of `object`, when present, must be an array; `check` sees each element.
    static void forEach(const Json& object, const char* key, const Check& check, const std::string& path = "") {
        const Json* list = member(object, key);
        if (list == nullptr) return;
        const std::string here = join(path, key);
        if (!list->is_array()) fault(here, "expected an array, got " + typeName(*list));
        for (std::size_t i = 0; i < list->size(); ++i) check((*list)[i], here + "[" + std::to_string(i) + "]");
    }

    void node(const Json& v, const std::string& path) const {
        object(v, path);
        optional(v, path, "name", string);
        forEach(v, "children", [&](const Json& c, const std::string& p) { index(c, p, "nodes"); }, path);
        optional(v, path, "mesh", [&](const Json& n, const std::string& p) { index(n, p, "meshes"); });
        optional(v, path, "camera", [&](const Json& n, const std::string& p) { index(n, p, "cameras"); });
        optional(v, path, "skin", [&](const Json& n, const std::string& p) { index(n, p, "skins"); });
        optional(v, path, "matrix", [](const Json& n, const std::string& p) { numbers(n, p, 16); });
        optional(v, path, "translation", [](const Json& n, const std::string& p) { numbers(n, p, 3); });
        optional(v, path, "rotation", [](const Json& n, const std::string& p) { numbers(n, p, 4, -1.0, 1.0); });
        optional(v, path, "scale", [](const Json& n, const std::string& p) { numbers(n, p, 3); });
        if (const Json* extensions = member(v, "extensions")) {
            const std::string ep = join(path, "extensions");
            object(*extensions, ep);
            optional(*extensions, ep, "KHR_lights_punctual", [&](const Json& e, const std::string& p) {
                object(e, p);
                required(e, p, "light", [&](const Json& n, const std::string& q) { lightIndex(n, q); });
            });
        }
    }

    void mesh(const Json& v, const std::string& path) const {
        object(v, path);
        optional(v, path, "name", string);
        required(v, path, "primitives", [&](const Json& list, const std::string& p) {
            if (!list.is_array()) fault(p, "expected an array, got " + typeName(list));
            if (list.empty()) fault(p, "expected at least one primitive, got an empty array");
        });
        forEach(v, "primitives", [&](const Json& prim, const std::string& p) { primitive(prim, p); }, path);
    }

    void primitive(const Json& v, const std::string& path) const {
        object(v, path);
        required(v, path, "attributes", [&](const Json& attributes, const std::string& p) {
            object(attributes, p);
            for (auto it = attributes.begin(); it != attributes.end(); ++it)
                index(it.value(), p + "." + it.key(), "accessors");
        });
        optional(v, path, "indices", [&](const Json& n, const std::string& p) { index(n, p, "accessors"); });
        optional(v, path, "material", [&](const Json& n, const std::string& p) { index(n, p, "materials"); });
        optional(v, path, "mode", [](const Json& n, const std::string& p) { oneOf(n, p, {0, 1, 2, 3, 4, 5, 6}); });
        forEach(v, "targets", [&](const Json& target, const std::string& p) {
            object(target, p);
            for (auto it = target.begin(); it != target.end(); ++it) index(it.value(), p + "." + it.key(), "accessors");
        }, path);
    }

    void accessor(const Json& v, const std::string& path) const {
        object(v, path);
        optional(v, path, "bufferView", [&](const Json& n, const std::string& p) { index(n, p, "bufferViews"); });
        optional(v, path, "byteOffset", [](const Json& n, const std::string& p) { integer(n, p, 0); });
        required(v, path, "componentType",
                 [](const Json& n, const std::string& p) { oneOf(n, p, {5120, 5121, 5122, 5123, 5125, 5126}); });
        optional(v, path, "normalized", boolean);
        required(v, path, "count", [](const Json& n, const std::string& p) { integer(n, p, 1); });
        required(v, path, "type", [](const Json& n, const std::string& p) {
            oneOf(n, p, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"});
        });
        optional(v, path, "sparse", object);
    }

    void bufferView(const Json& v, const std::string& path) const {
        object(v, path);
        required(v, path, "buffer", [&](const Json& n, const std::string& p) { index(n, p, "buffers"); });
        optional(v, path, "byteOffset", [](const Json& n, const std::string& p) { integer(n, p, 0); });
        required(v, path, "byteLength", [](const Json& n, const std::string& p) { integer(n, p, 1); });
        optional(v, path, "byteStride", [](const Json& n, const std::string& p) {
            if (integer(n, p, 4) > 252) fault(p, "expected an integer from 4 to 252, got " + n.dump());
        });
    }

    // A textureInfo (or normalTextureInfo / occlusionTextureInfo: `extra` names their number).
    void textureInfo(const Json& v, const std::string& path, const char* extra = nullptr, double extraMax = 1e300) const {
        object(v, path);
        required(v, path, "index", [&](const Json& n, const std::string& p) { index(n, p, "textures"); });
        optional(v, path, "texCoord", [](const Json& n, const std::string& p) { integer(n, p, 0); });
        if (extra != nullptr)
            optional(v, path, extra, [&](const Json& n, const std::string& p) {
                number(n, p, extraMax < 1e300 ? 0.0 : -1e300, extraMax);
            });
    }

    void material(const Json& v, const std::string& path) const {
        object(v, path);
        optional(v, path, "name", string);
        optional(v, path, "pbrMetallicRoughness", [&](const Json& pbr, const std::string& p) {
            object(pbr, p);
            optional(pbr, p, "baseColorFactor", [](const Json& n, const std::string& q) { numbers(n, q, 4, 0.0, 1.0); });
            optional(pbr, p, "baseColorTexture", [&](const Json& n, const std::string& q) { textureInfo(n, q); });
            optional(pbr, p, "metallicFactor", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1.0); });
            optional(pbr, p, "roughnessFactor", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1.0); });
            optional(pbr, p, "metallicRoughnessTexture", [&](const Json& n, const std::string& q) { textureInfo(n, q); });
        });
        optional(v, path, "normalTexture", [&](const Json& n, const std::string& p) { textureInfo(n, p, "scale"); });
        optional(v, path, "occlusionTexture",
                 [&](const Json& n, const std::string& p) { textureInfo(n, p, "strength", 1.0); });
        optional(v, path, "emissiveTexture", [&](const Json& n, const std::string& p) { textureInfo(n, p); });
        optional(v, path, "emissiveFactor", [](const Json& n, const std::string& p) { numbers(n, p, 3, 0.0, 1.0); });
        optional(v, path, "alphaMode", [](const Json& n, const std::string& p) { oneOf(n, p, {"OPAQUE", "MASK", "BLEND"}); });
        optional(v, path, "alphaCutoff", [](const Json& n, const std::string& p) { number(n, p, 0.0); });
        optional(v, path, "doubleSided", boolean);
        const Json* extensions = member(v, "extensions");
        if (extensions == nullptr) return;
        const std::string ep = join(path, "extensions");
        object(*extensions, ep);
        optional(*extensions, ep, "KHR_materials_emissive_strength", [](const Json& e, const std::string& p) {
            object(e, p);
            optional(e, p, "emissiveStrength", [](const Json& n, const std::string& q) { number(n, q, 0.0); });
        });
        optional(*extensions, ep, "T10_materials_parallax", [&](const Json& e, const std::string& p) {
            object(e, p);
            optional(e, p, "depthTexture", [&](const Json& n, const std::string& q) { textureInfo(n, q); });
            optional(e, p, "parallaxScale", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1.0); });
            optional(e, p, "shininess", [](const Json& n, const std::string& q) { number(n, q, 1.0); });
            optional(e, p, "specular", [](const Json& n, const std::string& q) { number(n, q, 0.0); });
        });
    }

    static void sampler(const Json& v, const std::string& path) {
        object(v, path);
        optional(v, path, "magFilter", [](const Json& n, const std::string& p) { oneOf(n, p, {9728, 9729}); });
        optional(v, path, "minFilter",
                 [](const Json& n, const std::string& p) { oneOf(n, p, {9728, 9729, 9984, 9985, 9986, 9987}); });
        for (const char* wrap : {"wrapS", "wrapT"})
            optional(v, path, wrap, [](const Json& n, const std::string& p) { oneOf(n, p, {33071, 33648, 10497}); });
    }

    static void camera(const Json& v, const std::string& path) {
        object(v, path);
        optional(v, path, "name", string);
        required(v, path, "type", [](const Json& n, const std::string& p) { oneOf(n, p, {"perspective", "orthographic"}); });
        optional(v, path, "perspective", [](const Json& c, const std::string& p) {
            object(c, p);
            required(c, p, "yfov", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1e300, true); });
            required(c, p, "znear", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1e300, true); });
            optional(c, p, "zfar", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1e300, true); });
            optional(c, p, "aspectRatio", [](const Json& n, const std::string& q) { number(n, q, 0.0, 1e300, true); });
        });
        optional(v, path, "orthographic", object);
        // The loader shows extras.description as the camera's description.
        if (const Json* extras = member(v, "extras"))
            optional(*extras, join(path, "extras"), "description", string);
    }

    static void light(const Json& v, const std::string& path) {
        object(v, path);
        optional(v, path, "name", string);
        required(v, path, "type", [](const Json& n, const std::string& p) { oneOf(n, p, {"directional", "point", "spot"}); });
        optional(v, path, "color", [](const Json& n, const std::string& p) { numbers(n, p, 3, 0.0, 1.0); });
        optional(v, path, "intensity", [](const Json& n, const std::string& p) { number(n, p, 0.0); });
        optional(v, path, "range", [](const Json& n, const std::string& p) { number(n, p, 0.0, 1e300, true); });
        optional(v, path, "spot", [](const Json& s, const std::string& p) {
            object(s, p);
            const double quarter = 1.5707963267948966;
            optional(s, p, "innerConeAngle", [&](const Json& n, const std::string& q) { number(n, q, 0.0, quarter); });
            optional(s, p, "outerConeAngle", [&](const Json& n, const std::string& q) { number(n, q, 0.0, quarter); });
        });
    }

    const Json& root_;
};

std::uint32_t readU32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

} // namespace

std::optional<std::string> gltfSchemaFault(const std::uint8_t* bytes, std::size_t size) {
    const std::uint8_t* json = bytes;
    std::size_t length = size;
    if (size >= 4 && std::memcmp(bytes, "glTF", 4) == 0) {
        // GLB: 12-byte header, then the JSON chunk (length, "JSON", data).
        if (size < 20 || readU32(bytes + 16) != 0x4E4F534Au) return std::nullopt;
        const std::uint32_t chunk = readU32(bytes + 12);
        if (chunk > size - 20) return std::nullopt;
        json = bytes + 20;
        length = chunk;
    }
    const Json root = Json::parse(json, json + length, nullptr, false);
    if (root.is_discarded()) return std::nullopt;
    try {
        Checker(root).run();
    } catch (const SchemaFault& fault) {
        return fault.what;
    }
    return std::nullopt;
}

} // namespace t10
