// glTF 2.0 into a SceneDescription: tinygltf parses the JSON/GLB and resolves buffers and images;
// everything after that (accessor bounds, indices, node graph, numbers) is checked here before use.
#include "t10/gltf_scene.hpp"

#include "t10/error.hpp"
#include "t10/gltf_schema.hpp"
#include "t10/stb_guard.hpp"
#include "t10/file.hpp"
#include "t10/tga.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <type_traits>

namespace t10 {

namespace {

constexpr const char* kParallaxExtension = "T10_materials_parallax";
constexpr const char* kUvBoundsAttribute = "_T10_UV_BOUNDS";
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kLightsPunctual = "KHR_lights_punctual";
// Extensions this loader implements; a file that REQUIRES any other is refused by name.
const std::set<std::string> kSupportedExtensions{kParallaxExtension, kEmissiveStrength, kLightsPunctual};

// A fault in the file: caught at the top and prefixed with the file name.
struct Fault {
    std::string what;
};

[[noreturn]] void fail(const std::string& what) {
    throw Fault{what};
}

bool endsWithNoCase(const std::string& text, const std::string& suffix) {
    if (text.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[text.size() - suffix.size() + i]);
        if (std::tolower(c) != suffix[i]) return false;
    }
    return true;
}

// --- Images: PNG and JPEG through stb, TGA through the project's loader. ------------------------

struct ImageContext {
    const GltfLoadLimits* limits;
    std::size_t pixels = 0; // all images so far
};

bool loadImage(tinygltf::Image* image, int index, std::string* err, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    auto& context = *static_cast<ImageContext*>(user);
    const std::string label = "image " + std::to_string(index) + (image->uri.empty() || image->uri.size() > 200
                                                                       ? std::string()
                                                                       : " (" + image->uri + ")");
    auto refuse = [&](const std::string& why) {
        if (err) *err += label + ": " + why + "\n";
        return false;
    };
    if (bytes == nullptr || size <= 0) return refuse("no data");
    const bool tga = endsWithNoCase(image->uri, ".tga") || image->mimeType == "image/x-tga" ||
                     image->mimeType == "image/tga";
    Image8 decoded;
    if (tga) {
        try {
            decoded = decodeTga(bytes, static_cast<std::size_t>(size), label);
        } catch (const Error& error) {
            if (err) *err += std::string(error.what()) + "\n"; // "<label>: <fault>"
            return false;
        }
    } else {
        if (const auto fault = stbInputFault(bytes, static_cast<std::size_t>(size)))
            return refuse(*fault + (fault->rfind("not a", 0) == 0 ? " (TGA images need a .tga name or image/x-tga)" : ""));
        int w = 0;
        int h = 0;
        int channels = 0;
        if (!stbi_info_from_memory(bytes, size, &w, &h, &channels))
            return refuse(std::string("cannot decode: ") + stbi_failure_reason());
        if (w < 1 || h < 1 || w > context.limits->maxImageSide || h > context.limits->maxImageSide)
            return refuse("size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." +
                          std::to_string(context.limits->maxImageSide));
        // Grey+alpha becomes RGBA, grey stays grey, colour keeps its alpha or not.
        const int wanted = channels == 2 ? 4 : channels;
        std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(bytes, size, &w, &h, &channels, wanted),
                                                         &stbi_image_free);
        if (!pixels) return refuse(std::string("cannot decode: ") + stbi_failure_reason());
        decoded = Image8(w, h, wanted);
        // stb gives the top row first; images here are stored bottom row first.
        const std::size_t row = static_cast<std::size_t>(w) * static_cast<std::size_t>(wanted);
        for (int y = 0; y < h; ++y)
            std::memcpy(decoded.data.data() + static_cast<std::size_t>(h - 1 - y) * row,
                        pixels.get() + static_cast<std::size_t>(y) * row, row);
    }
    if (decoded.width > context.limits->maxImageSide || decoded.height > context.limits->maxImageSide)
        return refuse("size " + std::to_string(decoded.width) + "x" + std::to_string(decoded.height) + " is too large");
    context.pixels += static_cast<std::size_t>(decoded.width) * static_cast<std::size_t>(decoded.height);
    if (context.pixels > context.limits->maxImagePixels) return refuse("the images hold too many pixels in all");
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = decoded.channels;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.data);
    return true;
}

// --- File access for tinygltf: plain reads, no shell expansion, optionally none at all. ---------

bool fileExists(const std::string& path, void* user) {
    if (!static_cast<const GltfLoadLimits*>(user)->allowExternalFiles) return false;
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

std::string expandPath(const std::string& path, void*) {
    return path; // tinygltf's default runs wordexp(); a file name is only a file name here
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (!static_cast<const GltfLoadLimits*>(user)->allowExternalFiles) {
        if (err) *err += path + ": external files are not read here\n";
        return false;
    }
    std::error_code ignored;
    if (std::filesystem::exists(path, ignored) && !std::filesystem::is_regular_file(path, ignored)) {
        if (err) *err += path + ": not a regular file\n"; // a device or FIFO could be endless
        return false;
    }
    try {
        *out = readFile(path);
    } catch (const Error& error) {
        if (err) *err += std::string(error.what()) + "\n"; // "<path>: cannot open file: <reason>"
        return false;
    }
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the loader writes no files\n";
    return false;
}

// tinygltf 2.8.13 added FsCallbacks::GetFileSizeInBytes (2.9, Debian 13, asks it before reading an
// external file) and 2.9 made SetFsCallbacks return false, keeping its default callbacks, when any
// callback is null; 2.7 (Debian 12) has neither. The callbacks are set by name and the size callback
// only where the field exists; a refusal is an error, never a silent fall-back to tinygltf's own.
[[maybe_unused]] bool fileSize(std::size_t* size, std::string* err, const std::string& path, void* user) {
    if (!static_cast<const GltfLoadLimits*>(user)->allowExternalFiles) {
        if (err) *err += path + ": external files are not read here\n";
        return false;
    }
    std::error_code error;
    const auto bytes = std::filesystem::file_size(path, error);
    if (error) {
        if (err) *err += path + ": cannot read the file's size: " + error.message() + "\n";
        return false;
    }
    *size = static_cast<std::size_t>(bytes);
    return true;
}

template <typename C, typename = void>
struct HasFileSizeCallback : std::false_type {};
template <typename C>
struct HasFileSizeCallback<C, std::void_t<decltype(std::declval<C&>().GetFileSizeInBytes)>> : std::true_type {};

// Callbacks is tinygltf::FsCallbacks, a template parameter so that `if constexpr` discards what it lacks.
template <typename Callbacks, typename Loader>
void setFsCallbacks(Loader& loader, const GltfLoadLimits& limits) {
    Callbacks fs{};
    fs.FileExists = &fileExists;
    fs.ExpandFilePath = &expandPath;
    fs.ReadWholeFile = &readWholeFile;
    fs.WriteWholeFile = &writeWholeFile;
    if constexpr (HasFileSizeCallback<Callbacks>::value) fs.GetFileSizeInBytes = &fileSize;
    fs.user_data = const_cast<GltfLoadLimits*>(&limits);
    if constexpr (std::is_same_v<decltype(loader.SetFsCallbacks(fs)), bool>) {
        if (!loader.SetFsCallbacks(fs)) fail("tinygltf refused the loader's file callbacks");
    } else {
        loader.SetFsCallbacks(fs);
    }
}

// --- Accessors: every offset and count checked against the bytes behind it. ---------------------

struct AccessorData {
    const std::uint8_t* base = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;

    // Component c of element i as float (normalised integers mapped as glTF says).
    float get(std::size_t i, int c) const {
        const std::uint8_t* p = base + i * stride;
        switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p + 4 * c, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const float v = p[c];
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = static_cast<std::int8_t>(p[c]);
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p + 2 * c, 2);
            return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p + 2 * c, 2);
            return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
        }
        default: { // UNSIGNED_INT (checked in accessorData)
            std::uint32_t v;
            std::memcpy(&v, p + 4 * c, 4);
            return static_cast<float>(v);
        }
        }
    }
    std::uint32_t index(std::size_t i) const {
        const std::uint8_t* p = base + i * stride;
        if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
        if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
};

int componentSize(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

// `what` names the use in messages ("mesh 0 primitive 1 POSITION"). `types` lists accepted
// component types; `components` the required component count.
AccessorData accessorData(const tinygltf::Model& model, int index, const std::string& what,
                          std::initializer_list<int> types, int components) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        fail(what + ": accessor " + std::to_string(index) + " does not exist (the file has " +
             std::to_string(model.accessors.size()) + ")");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    const std::string name = what + ": accessor " + std::to_string(index);
    if (a.sparse.isSparse) fail(name + " is sparse, which this loader does not read");
    if (std::find(types.begin(), types.end(), a.componentType) == types.end())
        fail(name + " has component type " + std::to_string(a.componentType) + ", not one allowed here");
    if (componentCount(a.type) != components)
        fail(name + " has " + std::to_string(componentCount(a.type)) + " components per element, expected " +
             std::to_string(components));
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
        fail(name + " refers to buffer view " + std::to_string(a.bufferView) + ", which does not exist");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        fail(name + ": buffer view " + std::to_string(a.bufferView) + " refers to buffer " +
             std::to_string(view.buffer) + ", which does not exist");
    const std::size_t bufferSize = model.buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset)
        fail(name + ": buffer view " + std::to_string(a.bufferView) + " (offset " + std::to_string(view.byteOffset) +
             ", length " + std::to_string(view.byteLength) + ") lies outside buffer " + std::to_string(view.buffer) +
             " (" + std::to_string(bufferSize) + " bytes)");
    const std::size_t element = static_cast<std::size_t>(componentSize(a.componentType)) *
                                static_cast<std::size_t>(components);
    std::size_t stride = view.byteStride == 0 ? element : view.byteStride;
    if (view.byteStride != 0 && (view.byteStride < element || view.byteStride > 252))
        fail(name + ": byte stride " + std::to_string(view.byteStride) + " is not between the element size " +
             std::to_string(element) + " and 252");
    AccessorData data;
    data.count = a.count;
    if (a.count > 0) {
        // offset + stride * (count - 1) + element <= view length, without overflow.
        const std::size_t length = view.byteLength;
        const bool fits = a.byteOffset <= length && element <= length - a.byteOffset &&
                          (a.count - 1) <= (length - a.byteOffset - element) / stride;
        if (!fits)
            fail(name + " (" + std::to_string(a.count) + " elements from offset " + std::to_string(a.byteOffset) +
                 ") reads past the end of buffer view " + std::to_string(a.bufferView) + " (" +
                 std::to_string(length) + " bytes)");
        data.base = model.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + a.byteOffset;
    }
    data.stride = stride;
    data.componentType = a.componentType;
    data.components = components;
    data.normalized = a.normalized;
    return data;
}

// --- Small checked readers of the JSON numbers tinygltf keeps as doubles. -----------------------

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

float finiteNumber(double value, const std::string& what) {
    if (!std::isfinite(value) || std::abs(value) > 1.0e30) fail(what + " is not a finite number");
    return static_cast<float>(value);
}

glm::mat4 nodeMatrix(const tinygltf::Node& node, const std::string& what) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(what + ": matrix has " + std::to_string(node.matrix.size()) + " numbers, not 16");
        glm::mat4 m(1.0f);
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = finiteNumber(node.matrix[static_cast<std::size_t>(i)], what + " matrix");
        return m;
    }
    glm::vec3 t(0.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    glm::vec3 s(1.0f);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) fail(what + ": translation does not have 3 numbers");
        for (int i = 0; i < 3; ++i) t[i] = finiteNumber(node.translation[static_cast<std::size_t>(i)], what + " translation");
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) fail(what + ": rotation does not have 4 numbers");
        // glTF stores x, y, z, w.
        r = glm::quat(finiteNumber(node.rotation[3], what + " rotation"), finiteNumber(node.rotation[0], what + " rotation"),
                      finiteNumber(node.rotation[1], what + " rotation"), finiteNumber(node.rotation[2], what + " rotation"));
        const float length = glm::length(r);
        if (!(length > 1e-6f)) fail(what + ": rotation is not a unit quaternion");
        r = r / length;
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) fail(what + ": scale does not have 3 numbers");
        for (int i = 0; i < 3; ++i) s[i] = finiteNumber(node.scale[static_cast<std::size_t>(i)], what + " scale");
    }
    return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
}

// A number from an extension object, with its type checked.
float extensionNumber(const tinygltf::Value& object, const char* key, float fallback, const std::string& what) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) fail(what + ": '" + key + "' is not a number");
    return finiteNumber(v.GetNumberAsDouble(), what + " '" + key + "'");
}

// --- The conversion. -----------------------------------------------------------------------------

class Converter {
public:
    Converter(const tinygltf::Model& model, const GltfLoadLimits& limits, SceneDescription& out)
        : model_(model), limits_(limits), out_(out) {}

    void run() {
        checkExtensions();
        convertMaterials();
        traverseNodes();
        refuseNothingToDraw();
        if (!model_.animations.empty()) warn("animations are ignored; the scene is drawn at rest");
        computeBounds();
        if (out_.lights.size() > kMaxSceneLights)
            warn("the file has " + std::to_string(out_.lights.size()) + " lights; the first " +
                 std::to_string(kMaxSceneLights) + " are used");
        if (out_.lights.empty()) addDefaultLights();
        addFramingCamera();
    }

private:
    void warn(const std::string& text) {
        if (std::find(out_.warnings.begin(), out_.warnings.end(), text) == out_.warnings.end())
            out_.warnings.push_back(text);
    }

    // A scene without a single triangle would render an empty frame and exit 0: refused, with why.
    void refuseNothingToDraw() const {
        if (out_.triangleCount > 0) return;
        if (model_.meshes.empty()) fail("nothing to draw: the file has no meshes");
        if (meshNodes_ == 0)
            fail("nothing to draw: no node of the scene refers to a mesh (the file has " +
                 std::to_string(model_.meshes.size()) + ")");
        const std::string count = std::to_string(primitives_) + (primitives_ == 1 ? " primitive" : " primitives");
        if (pointsOrLines_ == primitives_)
            fail("nothing to draw: " + std::string(primitives_ == 1 ? "the scene's only primitive is" : "the scene's " + count + " are all") +
                 " points or lines, which are not drawn");
        fail("nothing to draw: every primitive was skipped (" + count + ": " + std::to_string(pointsOrLines_) +
             " points or lines, " + std::to_string(primitives_ - pointsOrLines_) + " without a whole triangle)");
    }

    void checkExtensions() {
        for (const std::string& name : model_.extensionsRequired) {
            if (!kSupportedExtensions.count(name))
                fail("requires the extension " + name + ", which this loader does not support");
        }
        for (const std::string& name : model_.extensionsUsed) {
            if (!kSupportedExtensions.count(name)) warn("the optional extension " + name + " is ignored");
        }
    }

    // Textures are made per (image, sampler, colour space) combination as materials ask for them.
    int texture(int index, bool srgb, int texCoord, const std::string& what) {
        if (index < 0) return -1;
        if (static_cast<std::size_t>(index) >= model_.textures.size())
            fail(what + ": texture " + std::to_string(index) + " does not exist");
        if (texCoord != 0) warn(what + " uses TEXCOORD_" + std::to_string(texCoord) + "; TEXCOORD_0 is used instead");
        const tinygltf::Texture& t = model_.textures[static_cast<std::size_t>(index)];
        if (t.source < 0 || static_cast<std::size_t>(t.source) >= model_.images.size())
            fail(what + ": texture " + std::to_string(index) + " has no valid image source");
        const tinygltf::Image& image = model_.images[static_cast<std::size_t>(t.source)];
        const std::string imageName = "image " + std::to_string(t.source) +
                                      (image.uri.empty() || image.uri.size() > 200 ? "" : " (" + image.uri + ")");
        if (image.image.empty() || image.width < 1 || image.height < 1)
            fail(imageName + " is missing or could not be decoded");
        SamplerSettings sampler;
        if (t.sampler >= 0) {
            if (static_cast<std::size_t>(t.sampler) >= model_.samplers.size())
                fail(what + ": sampler " + std::to_string(t.sampler) + " does not exist");
            const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(t.sampler)];
            auto check = [&](int value, std::initializer_list<int> allowed, const char* field) {
                if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
                    fail("sampler " + std::to_string(t.sampler) + ": " + field + " " + std::to_string(value) +
                         " is not a glTF value");
                return value;
            };
            if (s.minFilter != -1)
                sampler.minFilter = check(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}, "minFilter");
            if (s.magFilter != -1) sampler.magFilter = check(s.magFilter, {9728, 9729}, "magFilter");
            sampler.wrapS = check(s.wrapS, {33071, 33648, 10497}, "wrapS");
            sampler.wrapT = check(s.wrapT, {33071, 33648, 10497}, "wrapT");
        }
        const int imageIndex = imageFor(t.source);
        if (image.component != 1 && image.component != 3 && image.component != 4)
            fail(imageName + " has " + std::to_string(image.component) + " channels");
        for (std::size_t i = 0; i < out_.textures.size(); ++i) {
            const SceneTexture& e = out_.textures[i];
            if (e.image == imageIndex && e.srgb == srgb && e.sampler.minFilter == sampler.minFilter &&
                e.sampler.magFilter == sampler.magFilter && e.sampler.wrapS == sampler.wrapS &&
                e.sampler.wrapT == sampler.wrapT)
                return static_cast<int>(i);
        }
        out_.textures.push_back({imageIndex, srgb, sampler});
        return static_cast<int>(out_.textures.size() - 1);
    }

    int imageFor(int source) {
        auto it = imageIndex_.find(source);
        if (it != imageIndex_.end()) return it->second;
        const tinygltf::Image& image = model_.images[static_cast<std::size_t>(source)];
        Image8 converted;
        converted.width = image.width;
        converted.height = image.height;
        converted.channels = image.component;
        const std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                     static_cast<std::size_t>(std::max(image.component, 0));
        if (image.image.size() != expected || image.bits != 8)
            fail("image " + std::to_string(source) + ": decoded data does not match its size");
        converted.data = image.image;
        out_.images.push_back(std::move(converted));
        const int index = static_cast<int>(out_.images.size() - 1);
        imageIndex_[source] = index;
        return index;
    }

    void convertMaterials() {
        for (std::size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& m = model_.materials[i];
            const std::string what = "material " + std::to_string(i) + (m.name.empty() ? "" : " (" + m.name + ")");
            SceneMaterial s;
            s.name = m.name;
            const auto& pbr = m.pbrMetallicRoughness;
            if (pbr.baseColorFactor.size() != 4) fail(what + ": baseColorFactor does not have 4 numbers");
            for (int c = 0; c < 4; ++c)
                s.baseColour[c] = finiteNumber(pbr.baseColorFactor[static_cast<std::size_t>(c)], what + " baseColorFactor");
            s.baseColourTexture = texture(pbr.baseColorTexture.index, true, pbr.baseColorTexture.texCoord,
                                          what + " baseColorTexture");
            s.normalTexture = texture(m.normalTexture.index, false, m.normalTexture.texCoord, what + " normalTexture");
            s.normalScale = finiteNumber(m.normalTexture.scale, what + " normalTexture.scale");
            if (m.emissiveFactor.size() != 3) fail(what + ": emissiveFactor does not have 3 numbers");
            for (int c = 0; c < 3; ++c)
                s.emissive[c] = finiteNumber(m.emissiveFactor[static_cast<std::size_t>(c)], what + " emissiveFactor");
            s.emissiveTexture = texture(m.emissiveTexture.index, true, m.emissiveTexture.texCoord, what + " emissiveTexture");
            auto strength = m.extensions.find(kEmissiveStrength);
            if (strength != m.extensions.end()) {
                if (!strength->second.IsObject()) fail(what + ": " + kEmissiveStrength + " is not an object");
                const float k = extensionNumber(strength->second, "emissiveStrength", 1.0f, what + " " + kEmissiveStrength);
                if (k < 0.0f) fail(what + ": emissiveStrength is negative");
                s.emissive *= k;
            }
            // Blinn-Phong from metallic-roughness (the scene's shading model is not PBR): the
            // exponent of the Beckmann-equivalent lobe, and a weight falling with roughness.
            const float roughness = std::clamp(finiteNumber(pbr.roughnessFactor, what + " roughnessFactor"), 0.0f, 1.0f);
            const float metallic = std::clamp(finiteNumber(pbr.metallicFactor, what + " metallicFactor"), 0.0f, 1.0f);
            const float alpha = std::max(roughness * roughness, 0.03f);
            s.shininess = std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 1024.0f);
            s.specular = (1.0f - roughness) * (0.04f + 0.96f * metallic);
            if (pbr.metallicRoughnessTexture.index >= 0) warn(what + ": metallicRoughnessTexture is ignored (factors only)");
            if (m.occlusionTexture.index >= 0) warn(what + ": occlusionTexture is ignored");
            auto parallax = m.extensions.find(kParallaxExtension);
            if (parallax != m.extensions.end()) {
                const tinygltf::Value& p = parallax->second;
                const std::string pw = what + " " + kParallaxExtension;
                if (!p.IsObject()) fail(pw + " is not an object");
                if (p.Has("depthTexture")) {
                    const tinygltf::Value& info = p.Get("depthTexture");
                    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
                        fail(pw + ": depthTexture has no integer 'index'");
                    s.depthTexture = texture(info.Get("index").Get<int>(), false, 0, pw + " depthTexture");
                }
                s.parallaxScale = extensionNumber(p, "parallaxScale", 0.0f, pw);
                if (s.parallaxScale < 0.0f || s.parallaxScale > 1.0f) fail(pw + ": parallaxScale is outside 0..1");
                s.shininess = extensionNumber(p, "shininess", s.shininess, pw);
                s.specular = extensionNumber(p, "specular", s.specular, pw);
                if (s.shininess < 1.0f || s.specular < 0.0f) fail(pw + ": shininess below 1 or negative specular");
            }
            if (m.alphaMode == "MASK") s.alphaMode = AlphaMode::Mask;
            else if (m.alphaMode == "BLEND") s.alphaMode = AlphaMode::Blend;
            else if (m.alphaMode != "OPAQUE") fail(what + ": alphaMode '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND");
            s.alphaCutoff = finiteNumber(m.alphaCutoff, what + " alphaCutoff");
            s.doubleSided = m.doubleSided;
            out_.materials.push_back(std::move(s));
        }
        // Primitives without a material get glTF's default: white, rough, not metallic.
        defaultMaterial_ = static_cast<int>(out_.materials.size());
        SceneMaterial fallback;
        fallback.name = "(default)";
        fallback.shininess = 1.0f;
        fallback.specular = 0.0f;
        out_.materials.push_back(fallback);
    }

    void traverseNodes() {
        const std::size_t nodeCount = model_.nodes.size();
        // Each node has at most one parent; checking this first also bounds the traversal.
        std::vector<int> parent(nodeCount, -1);
        for (std::size_t i = 0; i < nodeCount; ++i) {
            for (const int child : model_.nodes[i].children) {
                if (child < 0 || static_cast<std::size_t>(child) >= nodeCount)
                    fail("node " + std::to_string(i) + " has child " + std::to_string(child) + ", which does not exist");
                if (parent[static_cast<std::size_t>(child)] != -1)
                    fail("node " + std::to_string(child) + " has two parents (nodes " +
                         std::to_string(parent[static_cast<std::size_t>(child)]) + " and " + std::to_string(i) + ")");
                parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
            }
        }
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int scene = model_.defaultScene;
            if (scene < 0) scene = 0;
            if (static_cast<std::size_t>(scene) >= model_.scenes.size())
                fail("default scene " + std::to_string(scene) + " does not exist");
            for (const int n : model_.scenes[static_cast<std::size_t>(scene)].nodes) {
                if (n < 0 || static_cast<std::size_t>(n) >= nodeCount)
                    fail("scene " + std::to_string(scene) + " lists node " + std::to_string(n) + ", which does not exist");
                if (parent[static_cast<std::size_t>(n)] != -1)
                    fail("scene " + std::to_string(scene) + " lists node " + std::to_string(n) +
                         ", which is not a root (node cycle or shared node)");
                roots.push_back(n);
            }
        } else {
            for (std::size_t i = 0; i < nodeCount; ++i)
                if (parent[i] == -1) roots.push_back(static_cast<int>(i));
        }
        // Depth-first with an explicit stack: no recursion, so no depth limit to overflow. A node
        // seen twice means a cycle (every node has one parent, so a tree never repeats one).
        std::vector<char> visited(nodeCount, 0);
        std::vector<std::pair<int, glm::mat4>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::mat4(1.0f));
        while (!stack.empty()) {
            const auto [index, parentMatrix] = stack.back();
            stack.pop_back();
            const auto n = static_cast<std::size_t>(index);
            if (visited[n]) fail("node " + std::to_string(index) + " is part of a cycle in the node hierarchy");
            visited[n] = 1;
            const tinygltf::Node& node = model_.nodes[n];
            const std::string what = "node " + std::to_string(index) + (node.name.empty() ? "" : " (" + node.name + ")");
            const glm::mat4 world = parentMatrix * nodeMatrix(node, what);
            if (node.mesh >= 0) {
                ++meshNodes_;
                addMesh(node, world, what);
            }
            if (node.camera >= 0) addCamera(node, world, what);
            addLight(node, world, what);
            if (node.skin >= 0) warn(what + " is skinned; it is drawn in its rest pose");
            for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.emplace_back(*c, world);
        }
        if (model_.scenes.empty()) {
            // Every node was reachable from a root unless some of them form a cycle.
            for (std::size_t i = 0; i < nodeCount; ++i)
                if (!visited[i]) fail("node " + std::to_string(i) + " is part of a cycle in the node hierarchy");
        }
    }

    void addMesh(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
            fail(nodeName + ": mesh " + std::to_string(node.mesh) + " does not exist");
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
        const glm::mat3 linear(world);
        const float det = glm::determinant(linear);
        if (!std::isfinite(det)) fail(nodeName + ": its world transform is not finite");
        const glm::mat3 normalMatrix = std::abs(det) > 1e-30f ? glm::transpose(glm::inverse(linear)) : linear;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string what = "mesh " + std::to_string(node.mesh) + (mesh.name.empty() ? "" : " (" + mesh.name + ")") +
                                     " primitive " + std::to_string(p);
            addPrimitive(mesh.primitives[p], world, normalMatrix, det < 0.0f, what);
        }
    }

    std::vector<std::uint32_t> triangleIndices(const tinygltf::Primitive& prim, std::size_t vertexCount,
                                               const std::string& what) {
        std::vector<std::uint32_t> raw;
        if (prim.indices >= 0) {
            const AccessorData idx = accessorData(model_, prim.indices, what + " indices",
                                                  {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                                  1);
            raw.resize(idx.count); // backed by the buffer view: checked in accessorData
            for (std::size_t i = 0; i < idx.count; ++i) {
                raw[i] = idx.index(i);
                if (raw[i] >= vertexCount)
                    fail(what + ": index " + std::to_string(raw[i]) + " (element " + std::to_string(i) +
                         ") is beyond the vertex count " + std::to_string(vertexCount));
            }
        } else {
            raw.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i) raw[i] = static_cast<std::uint32_t>(i);
        }
        std::vector<std::uint32_t> out;
        switch (prim.mode) {
        case TINYGLTF_MODE_TRIANGLES:
            if (raw.size() % 3 != 0) warn(what + ": a triangle list whose length is not a multiple of 3; the rest is dropped");
            out.assign(raw.begin(), raw.begin() + static_cast<std::ptrdiff_t>(raw.size() / 3 * 3));
            break;
        case TINYGLTF_MODE_TRIANGLE_STRIP:
            // Triangle i is (i, i+1, i+2) with every other one flipped to keep the winding.
            for (std::size_t i = 0; i + 2 < raw.size(); ++i) {
                const std::size_t odd = i % 2;
                out.insert(out.end(), {raw[i], raw[i + 1 + odd], raw[i + 2 - odd]});
            }
            break;
        case TINYGLTF_MODE_TRIANGLE_FAN:
            for (std::size_t i = 1; i + 1 < raw.size(); ++i) out.insert(out.end(), {raw[i], raw[i + 1], raw[0]});
            break;
        default: break;
        }
        return out;
    }

    // One primitive as a SceneMesh in world space; points and lines are counted and skipped.
    void addPrimitive(const tinygltf::Primitive& prim, const glm::mat4& world, const glm::mat3& normalMatrix,
                      bool mirrored, const std::string& what) {
        ++primitives_;
        switch (prim.mode) {
        case TINYGLTF_MODE_POINTS:
            ++pointsOrLines_;
            warn("points are not drawn (" + what + " and any others)");
            return;
        case TINYGLTF_MODE_LINE:
        case TINYGLTF_MODE_LINE_LOOP:
        case TINYGLTF_MODE_LINE_STRIP:
            ++pointsOrLines_;
            warn("lines are not drawn (" + what + " and any others)");
            return;
        case TINYGLTF_MODE_TRIANGLES:
        case TINYGLTF_MODE_TRIANGLE_STRIP:
        case TINYGLTF_MODE_TRIANGLE_FAN: break;
        default: fail(what + ": mode " + std::to_string(prim.mode) + " is not a glTF primitive mode");
        }
        if (!prim.targets.empty()) warn("morph targets are ignored; meshes are drawn at rest (" + what + " and any others)");
        auto attribute = [&](const char* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int positionIndex = attribute("POSITION");
        if (positionIndex < 0) fail(what + " has no POSITION attribute");
        const AccessorData positions =
            accessorData(model_, positionIndex, what + " POSITION", {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3);
        const std::size_t vertexCount = positions.count;
        std::vector<std::uint32_t> indices = triangleIndices(prim, vertexCount, what);
        if (indices.empty()) return;
        if (out_.triangleCount + indices.size() / 3 > limits_.maxTriangles)
            fail("the scene has more than " + std::to_string(limits_.maxTriangles) + " triangles");
        // Flat shading (no normals) makes three vertices per triangle.
        const std::size_t newVertices = std::max(vertexCount, attribute("NORMAL") < 0 ? indices.size() : 0);
        if (out_.vertexCount + newVertices > limits_.maxVertices)
            fail("the scene has more than " + std::to_string(limits_.maxVertices) + " vertices");

        int material = prim.material;
        if (material >= 0 && static_cast<std::size_t>(material) >= model_.materials.size())
            fail(what + ": material " + std::to_string(material) + " does not exist");
        if (material < 0) material = defaultMaterial_;

        SceneMesh mesh;
        mesh.name = what;
        mesh.material = material;
        readPositions(mesh, positions, world, what);
        auto optional = [&](const char* name, std::initializer_list<int> types, int components) {
            const int index = attribute(name);
            if (index < 0) return AccessorData{};
            AccessorData data = accessorData(model_, index, what + " " + name, types, components);
            if (data.count != vertexCount)
                fail(what + ": " + name + " has " + std::to_string(data.count) + " elements but POSITION has " +
                     std::to_string(vertexCount));
            return data;
        };
        readUvs(mesh,
                optional("TEXCOORD_0",
                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                         2),
                optional(kUvBoundsAttribute, {TINYGLTF_COMPONENT_TYPE_FLOAT}, 4), what);
        const AccessorData normals = optional("NORMAL", {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3);
        const AccessorData tangents = optional("TANGENT", {TINYGLTF_COMPONENT_TYPE_FLOAT}, 4);

        if (mirrored)
            for (std::size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
        readNormals(mesh, indices, normals, normalMatrix, what);
        mesh.indices = std::move(indices);
        if (tangents.count != 0 && normals.count != 0) readTangents(mesh, tangents, world, mirrored, what);
        else generateTangents(mesh);
        for (const SceneVertex& v : mesh.vertices) {
            out_.boundsMin = haveBounds_ ? glm::min(out_.boundsMin, v.position) : v.position;
            out_.boundsMax = haveBounds_ ? glm::max(out_.boundsMax, v.position) : v.position;
            haveBounds_ = true;
        }
        out_.triangleCount += mesh.indices.size() / 3;
        out_.vertexCount += mesh.vertices.size();
        out_.meshes.push_back(std::move(mesh));
    }

    static void readPositions(SceneMesh& mesh, const AccessorData& positions, const glm::mat4& world,
                              const std::string& what) {
        mesh.vertices.resize(positions.count); // positions.count is backed by the buffer
        for (std::size_t i = 0; i < positions.count; ++i) {
            const glm::vec3 p(positions.get(i, 0), positions.get(i, 1), positions.get(i, 2));
            if (!finite(p)) fail(what + ": POSITION " + std::to_string(i) + " is not finite");
            const glm::vec3 w = glm::vec3(world * glm::vec4(p, 1.0f));
            if (!finite(w)) fail(what + ": POSITION " + std::to_string(i) + " is not finite in world space");
            mesh.vertices[i].position = w;
            mesh.vertices[i].uvBounds = glm::vec4(-kNoUvBound, -kNoUvBound, kNoUvBound, kNoUvBound);
        }
    }

    static void readUvs(SceneMesh& mesh, const AccessorData& uvs, const AccessorData& bounds, const std::string& what) {
        for (std::size_t i = 0; i < uvs.count; ++i) {
            // glTF's v = 0 is the image's top row; images here are stored bottom row first.
            const glm::vec2 uv(uvs.get(i, 0), 1.0f - uvs.get(i, 1));
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) fail(what + ": TEXCOORD_0 " + std::to_string(i) + " is not finite");
            mesh.vertices[i].uv = uv;
        }
        for (std::size_t i = 0; i < bounds.count; ++i) {
            const glm::vec4 b(bounds.get(i, 0), bounds.get(i, 1), bounds.get(i, 2), bounds.get(i, 3));
            mesh.vertices[i].uvBounds = glm::vec4(b.x, 1.0f - b.w, b.z, 1.0f - b.y);
        }
    }

    // The file's normals through the normal matrix, or (glTF: none given) flat shading, where each
    // triangle gets its own three vertices and `indices` is renumbered to match.
    static void readNormals(SceneMesh& mesh, std::vector<std::uint32_t>& indices, const AccessorData& normals,
                            const glm::mat3& normalMatrix, const std::string& what) {
        if (normals.count == 0) {
            std::vector<SceneVertex> flat;
            flat.reserve(indices.size());
            for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
                SceneVertex v[3] = {mesh.vertices[indices[t]], mesh.vertices[indices[t + 1]], mesh.vertices[indices[t + 2]]};
                glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
                n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
                for (SceneVertex& x : v) {
                    x.normal = n;
                    flat.push_back(x);
                }
            }
            mesh.vertices = std::move(flat);
            for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
            return;
        }
        for (std::size_t i = 0; i < normals.count; ++i) {
            const glm::vec3 n(normals.get(i, 0), normals.get(i, 1), normals.get(i, 2));
            if (!finite(n)) fail(what + ": NORMAL " + std::to_string(i) + " is not finite");
            const glm::vec3 w = normalMatrix * n;
            mesh.vertices[i].normal = glm::length(w) > 0.0f ? glm::normalize(w) : glm::vec3(0, 0, 1);
        }
    }

    static void readTangents(SceneMesh& mesh, const AccessorData& tangents, const glm::mat4& world, bool mirrored,
                             const std::string& what) {
        const glm::mat3 linear(world);
        for (std::size_t i = 0; i < tangents.count; ++i) {
            const glm::vec3 t(tangents.get(i, 0), tangents.get(i, 1), tangents.get(i, 2));
            const float sign = tangents.get(i, 3) < 0.0f ? -1.0f : 1.0f;
            if (!finite(t)) fail(what + ": TANGENT " + std::to_string(i) + " is not finite");
            SceneVertex& v = mesh.vertices[i];
            // The bitangent in the file's space, then both through the node's transform (a
            // mirroring transform keeps them consistent with the flipped winding).
            glm::vec3 tw = linear * t;
            tw = tw - v.normal * glm::dot(v.normal, tw);
            v.tangent = glm::length(tw) > 0.0f ? glm::normalize(tw) : anyPerpendicular(v.normal);
            // glTF: bitangent = cross(normal, tangent.xyz) * w, pointing up the image, which
            // is the direction of increasing v here (v is flipped).
            v.bitangent = glm::normalize(glm::cross(v.normal, v.tangent)) * sign * (mirrored ? -1.0f : 1.0f);
        }
    }

    static glm::vec3 anyPerpendicular(const glm::vec3& n) {
        const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        return glm::normalize(glm::cross(axis, n));
    }

    // Per-vertex tangents from the texture coordinates (dP = T du + B dv per triangle, summed over
    // the triangles at a vertex), made orthogonal to the normal; the bitangent keeps the
    // handedness the UVs give. Without UVs any perpendicular frame will do.
    static void generateTangents(SceneMesh& mesh) {
        std::vector<glm::vec3> tSum(mesh.vertices.size(), glm::vec3(0.0f));
        std::vector<glm::vec3> bSum(mesh.vertices.size(), glm::vec3(0.0f));
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const SceneVertex& a = mesh.vertices[mesh.indices[t]];
            const SceneVertex& b = mesh.vertices[mesh.indices[t + 1]];
            const SceneVertex& c = mesh.vertices[mesh.indices[t + 2]];
            const glm::vec3 e1 = b.position - a.position;
            const glm::vec3 e2 = c.position - a.position;
            const glm::vec2 d1 = b.uv - a.uv;
            const glm::vec2 d2 = c.uv - a.uv;
            const float r = d1.x * d2.y - d2.x * d1.y;
            if (std::abs(r) < 1e-20f) continue;
            const glm::vec3 tangent = (e1 * d2.y - e2 * d1.y) / r;
            const glm::vec3 bitangent = (e2 * d1.x - e1 * d2.x) / r;
            if (!finite(tangent) || !finite(bitangent)) continue;
            for (int k = 0; k < 3; ++k) {
                tSum[mesh.indices[t + static_cast<std::size_t>(k)]] += tangent;
                bSum[mesh.indices[t + static_cast<std::size_t>(k)]] += bitangent;
            }
        }
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            SceneVertex& v = mesh.vertices[i];
            glm::vec3 t = tSum[i] - v.normal * glm::dot(v.normal, tSum[i]);
            if (!(glm::length(t) > 1e-12f) || !finite(t)) t = anyPerpendicular(v.normal);
            v.tangent = glm::normalize(t);
            const float sign = glm::dot(glm::cross(v.normal, v.tangent), bSum[i]) < 0.0f ? -1.0f : 1.0f;
            v.bitangent = glm::cross(v.normal, v.tangent) * sign;
        }
    }

    void addCamera(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        if (static_cast<std::size_t>(node.camera) >= model_.cameras.size())
            fail(nodeName + ": camera " + std::to_string(node.camera) + " does not exist");
        const tinygltf::Camera& c = model_.cameras[static_cast<std::size_t>(node.camera)];
        const std::string what = "camera " + std::to_string(node.camera);
        if (c.type != "perspective") {
            warn(what + " is " + c.type + "; only perspective cameras are used");
            return;
        }
        CameraPreset preset;
        preset.name = !c.name.empty() ? c.name : !node.name.empty() ? node.name : what;
        preset.description = "camera of " + out_.source;
        if (c.extras.IsObject() && c.extras.Has("description") && c.extras.Get("description").IsString())
            preset.description = c.extras.Get("description").Get<std::string>();
        preset.position = glm::vec3(world[3]);
        const glm::vec3 forward = -glm::vec3(world[2]);
        if (!finite(preset.position) || !(glm::length(forward) > 0.0f)) fail(nodeName + ": camera transform is degenerate");
        const glm::vec2 yp = yawPitchOf(forward);
        preset.yawDegrees = yp.x;
        preset.pitchDegrees = yp.y;
        preset.fovDegrees = glm::degrees(finiteNumber(c.perspective.yfov, what + " yfov"));
        preset.nearPlane = finiteNumber(c.perspective.znear, what + " znear");
        preset.farPlane = c.perspective.zfar > 0.0 ? finiteNumber(c.perspective.zfar, what + " zfar")
                                                   : preset.nearPlane * 1.0e4f; // infinite: a finite stand-in
        if (!(preset.nearPlane > 0.0f) || !(preset.farPlane > preset.nearPlane))
            fail(what + ": znear must be positive and below zfar");
        if (!(preset.fovDegrees > 0.0f && preset.fovDegrees < 180.0f)) fail(what + ": yfov is outside (0, pi)");
        const glm::vec3 up = glm::normalize(glm::vec3(world[1]));
        const glm::vec3 levelRight = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        if (std::abs(glm::dot(up, levelRight)) > 0.01f) warn(what + " is rolled; the first-person camera keeps the horizon level");
        out_.cameras.push_back(preset);
    }

    void addLight(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        auto ext = node.extensions.find(kLightsPunctual);
        if (ext == node.extensions.end()) return;
        if (!ext->second.IsObject() || !ext->second.Has("light") || !ext->second.Get("light").IsInt())
            fail(nodeName + ": " + kLightsPunctual + " has no integer 'light'");
        const int index = ext->second.Get("light").Get<int>();
        if (index < 0 || static_cast<std::size_t>(index) >= model_.lights.size())
            fail(nodeName + ": light " + std::to_string(index) + " does not exist");
        const tinygltf::Light& l = model_.lights[static_cast<std::size_t>(index)];
        const std::string what = "light " + std::to_string(index) + (l.name.empty() ? "" : " (" + l.name + ")");
        if (l.type == "directional") {
            warn(what + " is directional; only point and spot lights are used");
            return;
        }
        if (l.type != "point" && l.type != "spot") fail(what + ": type '" + l.type + "' is not point, spot or directional");
        SceneLight s;
        s.name = l.name;
        s.spot = l.type == "spot";
        glm::vec3 colour(1.0f);
        if (!l.color.empty()) {
            if (l.color.size() != 3) fail(what + ": color does not have 3 numbers");
            for (int c = 0; c < 3; ++c) colour[c] = finiteNumber(l.color[static_cast<std::size_t>(c)], what + " color");
        }
        const float intensity = finiteNumber(l.intensity, what + " intensity");
        if (intensity < 0.0f) fail(what + ": intensity is negative");
        s.intensity = colour * intensity;
        s.range = finiteNumber(l.range, what + " range");
        if (s.range < 0.0f) fail(what + ": range is negative");
        s.position = glm::vec3(world[3]);
        const glm::vec3 dir = -glm::vec3(world[2]);
        s.direction = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0, 0, -1);
        if (s.spot) {
            const float inner = finiteNumber(l.spot.innerConeAngle, what + " innerConeAngle");
            const float outer = finiteNumber(l.spot.outerConeAngle, what + " outerConeAngle");
            if (!(inner >= 0.0f && inner < outer && outer <= 1.5707964f))
                fail(what + ": cone angles need 0 <= inner < outer <= pi/2");
            s.innerConeCos = std::cos(inner);
            s.outerConeCos = std::cos(outer);
        }
        if (!finite(s.position)) fail(nodeName + ": light position is not finite");
        out_.lights.push_back(s);
    }

    void computeBounds() {
        if (!haveBounds_) out_.boundsMin = out_.boundsMax = glm::vec3(0.0f);
    }

    // Without lights, a key light above and to the front-right of the scene, a weaker fill from
    // the left and a rim light behind, at distances and intensities that scale with its size.
    void addDefaultLights() {
        out_.defaultLights = true;
        const glm::vec3 centre = 0.5f * (out_.boundsMin + out_.boundsMax);
        const float radius = std::max(0.5f * glm::length(out_.boundsMax - out_.boundsMin), 1e-3f);
        auto add = [&](const char* name, glm::vec3 offset, float strength) {
            SceneLight l;
            l.name = name;
            l.position = centre + offset * radius;
            // Illuminance at the centre = strength (d = |offset| radius).
            l.intensity = glm::vec3(strength * glm::dot(offset, offset) * radius * radius);
            out_.lights.push_back(l);
        };
        add("default key", {1.5f, 2.0f, 2.0f}, 1.0f);
        add("default fill", {-2.0f, 0.5f, 1.5f}, 0.35f);
        add("default rim", {0.0f, 1.5f, -2.5f}, 0.5f);
    }

    // A camera that shows the whole scene: in front of it (+Z), slightly above, looking at the centre
    // of its bounds, as close as it can be with every corner of the bounding box inside the frame.
    // The frame's aspect is not known here, so the box is fitted into a square of the vertical field
    // of view (any frame at least as wide as it is tall shows all of it), filled to kFill.
    void addFramingCamera() {
        for (const CameraPreset& c : out_.cameras)
            if (c.name == "framing") return;
        constexpr float kFill = 0.95f; // the box's projection reaches 95% of the way to the edge
        const glm::vec3 centre = 0.5f * (out_.boundsMin + out_.boundsMax);
        const float radius = std::max(0.5f * glm::length(out_.boundsMax - out_.boundsMin), 1e-3f);
        CameraPreset c;
        c.name = "framing";
        c.description = "Shows the whole scene from the front (+Z), slightly above";
        c.fovDegrees = 50.0f;
        const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)); // from the centre to the camera
        const glm::vec3 forward = -direction;
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const glm::vec3 up = glm::cross(right, forward);
        const float slope = std::tan(glm::radians(0.5f * c.fovDegrees)) * kFill;
        // A corner at (x, y) across and z0 along the view from the centre is inside the frame from a
        // distance d when |x| and |y| are at most slope * (z0 + d).
        float distance = 0.0f;
        float nearest = std::numeric_limits<float>::max();
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? out_.boundsMax.x : out_.boundsMin.x, (i & 2) ? out_.boundsMax.y : out_.boundsMin.y,
                                   (i & 4) ? out_.boundsMax.z : out_.boundsMin.z);
            const glm::vec3 offset = corner - centre;
            const float z0 = glm::dot(offset, forward);
            const float across = std::max(std::abs(glm::dot(offset, right)), std::abs(glm::dot(offset, up)));
            distance = std::max({distance, across / slope - z0, 1e-3f * radius - z0});
            nearest = std::min(nearest, z0);
        }
        c.position = centre + direction * distance;
        const glm::vec2 yp = yawPitchOf(forward);
        c.yawDegrees = yp.x;
        c.pitchDegrees = yp.y;
        c.nearPlane = std::max((nearest + distance) * 0.5f, distance * 1.0e-3f);
        c.farPlane = (distance + radius) * 2.0f;
        out_.cameras.push_back(c);
    }

    const tinygltf::Model& model_;
    const GltfLoadLimits& limits_;
    SceneDescription& out_;
    std::map<int, int> imageIndex_;
    int defaultMaterial_ = -1;
    bool haveBounds_ = false;
    // For the reason a scene draws nothing: nodes with a mesh, primitives seen, points or lines among them.
    std::size_t meshNodes_ = 0;
    std::size_t primitives_ = 0;
    std::size_t pointsOrLines_ = 0;
};

SceneDescription load(const std::uint8_t* bytes, std::size_t size, const std::string& name, const std::string& baseDir,
                      const GltfLoadLimits& limits) {
    SceneDescription out;
    out.source = name;
    try {
        if (size > static_cast<std::size_t>(std::numeric_limits<unsigned int>::max()))
            fail("the file is larger than 4 GiB");
        // The raw JSON's types and ranges first: tinygltf would quietly default a wrongly typed value.
        if (const auto schemaFault = gltfSchemaFault(bytes, size)) fail(*schemaFault);
        tinygltf::TinyGLTF loader;
        ImageContext images{&limits};
        loader.SetImageLoader(&loadImage, &images);
        setFsCallbacks<tinygltf::FsCallbacks>(loader, limits);
        tinygltf::Model model;
        std::string error;
        std::string warning;
        const bool binary = size >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
        bool ok = false;
        try {
            ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes, static_cast<unsigned int>(size), baseDir)
                        : loader.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes),
                                                     static_cast<unsigned int>(size), baseDir);
        } catch (const std::exception& e) {
            fail(std::string("cannot be parsed: ") + e.what());
        }
        // tinygltf ends messages with newlines and may hold several; one line each.
        auto lines = [](std::string text) {
            while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
            for (char& c : text)
                if (c == '\n') c = ';';
            return text;
        };
        if (!ok) fail(error.empty() ? "cannot be parsed" : lines(error));
        if (!warning.empty()) out.warnings.push_back(lines(warning));
        Converter(model, limits, out).run();
    } catch (const Fault& fault) {
        throw Error(name + ": " + fault.what);
    } catch (const std::bad_alloc&) {
        throw Error(name + ": out of memory while loading");
    }
    return out;
}

} // namespace

const CameraPreset* SceneDescription::findCamera(const std::string& name) const {
    for (const CameraPreset& c : cameras)
        if (c.name == name) return &c;
    return nullptr;
}

std::string SceneDescription::cameraNames() const {
    std::string names;
    for (const CameraPreset& c : cameras) names += (names.empty() ? "" : ", ") + c.name;
    return names;
}

std::string builtInScenePath() {
    return std::string(T10_ASSET_DIR) + "/scene.gltf";
}

SceneDescription loadGltfScene(const std::string& path, const GltfLoadLimits& limits) {
    const std::vector<std::uint8_t> bytes = readFile(path); // throws "<path>: cannot open file: <reason>"
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    return load(bytes.data(), bytes.size(), path, baseDir.empty() ? "." : baseDir, limits);
}

SceneDescription loadGltfSceneFromMemory(const std::uint8_t* bytes, std::size_t size, const std::string& name,
                                         const std::string& baseDir, const GltfLoadLimits& limits) {
    return load(bytes, size, name, baseDir, limits);
}

} // namespace t10
