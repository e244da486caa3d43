// A small helper for the tools that write glTF files (tools/make_scene, tools/make_gltf_fixtures):
// appends typed data to buffer 0 and makes buffer views, accessors, images, textures, materials and
// nodes in a tinygltf::Model, then writes it as .gltf (external or embedded) or .glb through
// tinygltf's own writer.
#pragma once
#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace t10::gltf {

// tinygltf 2.8.13 and later (Debian 13: 2.9) keep a node's light in Node::light and write the node's
// KHR_lights_punctual extension from it, dropping an extension set by hand when Node::light is -1;
// 2.7 (Debian 12) has no such field and writes the extension as given. setNodeLight sets the field
// where it exists, so that both write the same file.
template <typename N, typename = void>
struct HasLightField : std::false_type {};
template <typename N>
struct HasLightField<N, std::void_t<decltype(std::declval<N&>().light)>> : std::true_type {};

template <typename N>
void setNodeLight(N& node, int light) {
    if constexpr (HasLightField<N>::value) node.light = light;
}

class Builder {
public:
    Builder() {
        model.asset.version = "2.0";
        model.asset.generator = "Tutorial 10 tools";
        model.buffers.emplace_back();
        model.scenes.emplace_back();
        model.defaultScene = 0;
    }

    tinygltf::Model model;

    // Appends raw bytes (4-byte aligned) as a new buffer view; returns its index.
    int view(const void* data, std::size_t bytes, int target = 0, std::size_t stride = 0) {
        std::vector<unsigned char>& bin = model.buffers[0].data;
        while (bin.size() % 4 != 0) bin.push_back(0);
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = bin.size();
        v.byteLength = bytes;
        v.byteStride = stride;
        v.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        bin.insert(bin.end(), p, p + bytes);
        model.bufferViews.push_back(v);
        return static_cast<int>(model.bufferViews.size() - 1);
    }

    int accessor(int bufferView, std::size_t offset, int componentType, int type, std::size_t count,
                 bool normalized = false) {
        tinygltf::Accessor a;
        a.bufferView = bufferView;
        a.byteOffset = offset;
        a.componentType = componentType;
        a.type = type;
        a.count = count;
        a.normalized = normalized;
        model.accessors.push_back(a);
        return static_cast<int>(model.accessors.size() - 1);
    }

    // Float attributes in their own tightly packed view. `withBounds` adds min/max (POSITION needs it).
    template <typename Vec>
    int floats(const std::vector<Vec>& values, bool withBounds = false) {
        constexpr int n = static_cast<int>(sizeof(Vec) / sizeof(float));
        const int type = n == 1 ? TINYGLTF_TYPE_SCALAR : n == 2 ? TINYGLTF_TYPE_VEC2 : n == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
        const int v = view(values.data(), values.size() * sizeof(Vec), TINYGLTF_TARGET_ARRAY_BUFFER);
        const int a = accessor(v, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size());
        if (withBounds && !values.empty()) {
            std::vector<double> lo(n, 1e300), hi(n, -1e300);
            for (const Vec& value : values) {
                const auto* f = reinterpret_cast<const float*>(&value);
                for (int i = 0; i < n; ++i) {
                    lo[i] = std::min(lo[i], double(f[i]));
                    hi[i] = std::max(hi[i], double(f[i]));
                }
            }
            model.accessors[a].minValues = lo;
            model.accessors[a].maxValues = hi;
        }
        return a;
    }

    // Indices stored as u8, u16 or u32 (componentType), in their own view.
    int indices(const std::vector<std::uint32_t>& values, int componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        std::vector<unsigned char> bytes;
        for (const std::uint32_t i : values) {
            if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                bytes.push_back(static_cast<unsigned char>(i));
            } else if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                const auto s = static_cast<std::uint16_t>(i);
                bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&s),
                             reinterpret_cast<const unsigned char*>(&s) + 2);
            } else {
                bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&i),
                             reinterpret_cast<const unsigned char*>(&i) + 4);
            }
        }
        const int v = view(bytes.data(), bytes.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        return accessor(v, 0, componentType, TINYGLTF_TYPE_SCALAR, values.size());
    }

    // An image by file name (relative to the .gltf), or its bytes embedded: in the buffer (GLB
    // style, bufferView + mimeType) or as a base64 data URI.
    int imageUri(const std::string& uri) {
        tinygltf::Image image;
        image.uri = uri;
        model.images.push_back(image);
        return static_cast<int>(model.images.size() - 1);
    }
    int imageEmbedded(const std::vector<unsigned char>& bytes, const std::string& mimeType, bool dataUri) {
        tinygltf::Image image;
        if (dataUri) {
            image.uri = "data:" + mimeType + ";base64," + base64(bytes);
        } else {
            image.bufferView = view(bytes.data(), bytes.size());
            image.mimeType = mimeType;
        }
        model.images.push_back(image);
        return static_cast<int>(model.images.size() - 1);
    }

    int texture(int image, int sampler = -1) {
        tinygltf::Texture t;
        t.source = image;
        t.sampler = sampler;
        model.textures.push_back(t);
        return static_cast<int>(model.textures.size() - 1);
    }

    int sampler(int minFilter, int magFilter, int wrapS, int wrapT) {
        tinygltf::Sampler s;
        s.minFilter = minFilter;
        s.magFilter = magFilter;
        s.wrapS = wrapS;
        s.wrapT = wrapT;
        model.samplers.push_back(s);
        return static_cast<int>(model.samplers.size() - 1);
    }

    int material(const tinygltf::Material& m) {
        model.materials.push_back(m);
        return static_cast<int>(model.materials.size() - 1);
    }

    int mesh(const std::string& name, const std::vector<tinygltf::Primitive>& primitives) {
        tinygltf::Mesh m;
        m.name = name;
        m.primitives = primitives;
        for (tinygltf::Primitive& p : m.primitives)
            if (p.mode < 0) p.mode = TINYGLTF_MODE_TRIANGLES; // tinygltf would write -1
        model.meshes.push_back(m);
        return static_cast<int>(model.meshes.size() - 1);
    }

    // A node; `root` also lists it in the scene.
    int node(const tinygltf::Node& n, bool root = true) {
        model.nodes.push_back(n);
        const int index = static_cast<int>(model.nodes.size() - 1);
        if (root) model.scenes[0].nodes.push_back(index);
        return index;
    }

    void use(const std::string& extension, bool required = false) {
        auto add = [&](std::vector<std::string>& list) {
            for (const std::string& e : list)
                if (e == extension) return;
            list.push_back(extension);
        };
        add(model.extensionsUsed);
        if (required) add(model.extensionsRequired);
    }

    // A point or spot light (KHR_lights_punctual) attached to `node`.
    void light(int nodeIndex, const tinygltf::Light& l) {
        use("KHR_lights_punctual");
        model.lights.push_back(l);
        tinygltf::Value::Object ext;
        ext["light"] = tinygltf::Value(static_cast<int>(model.lights.size() - 1));
        tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
        node.extensions["KHR_lights_punctual"] = tinygltf::Value(ext); // tinygltf 2.7 writes this
        setNodeLight(node, static_cast<int>(model.lights.size() - 1)); // 2.8.13+ writes from this
    }

    // Writes `path`: .glb puts buffer 0 into the binary chunk; .gltf writes it next to the file as
    // `binName`, or embeds it as a data URI when binName is empty.
    void write(const std::string& path, bool binary, const std::string& binName) {
        model.buffers[0].uri = binary ? "" : binName;
        tinygltf::TinyGLTF writer;
        writer.SetImageWriter(nullptr, nullptr); // images keep the URIs given above
        if (!writer.WriteGltfSceneToFile(&model, path, false, !binary && binName.empty(), true, binary))
            throw std::runtime_error(path + ": tinygltf could not write the file");
    }

    static std::string base64(const std::vector<unsigned char>& bytes) {
        static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        std::string out;
        std::size_t i = 0;
        for (; i + 2 < bytes.size(); i += 3) {
            const unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
            out += {table[(v >> 18) & 63], table[(v >> 12) & 63], table[(v >> 6) & 63], table[v & 63]};
        }
        if (i + 1 == bytes.size()) {
            const unsigned v = bytes[i] << 16;
            out += {table[(v >> 18) & 63], table[(v >> 12) & 63], '=', '='};
        } else if (i + 2 == bytes.size()) {
            const unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8);
            out += {table[(v >> 18) & 63], table[(v >> 12) & 63], table[(v >> 6) & 63], '='};
        }
        return out;
    }
};

} // namespace t10::gltf
