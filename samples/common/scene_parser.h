// The scene loader's value reader (samples/common/scene*.cpp only): every check names the value
// by its JSON Pointer and throws pfs::Error("<file>: <pointer>: <reason>").
#pragma once

#include "json_read.h"
#include "scene.h"
#include "util.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>

namespace pfs {

using json = nlohmann::json;

// Every check names the value by its JSON Pointer ("/fill/0/lo/2") and never prints a value
// that is not a scalar: an array or object is described by its type and size only, since a
// nested one could be arbitrarily large.
struct Parser {
    std::string file;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file + ": " + pointer_text(where) + ": " + what);
    }

    static std::string join(const std::string& path, const std::string& key) { return pointer_join(path, key); }
    static std::string join(const std::string& path, size_t index) { return pointer_join(path, std::to_string(index)); }

    // What a value is, for "found ...": a number as written, anything else by its type.
    static std::string describe(const json& j) {
        if (j.is_number()) return j.dump();  // a scalar: short, no recursion
        if (j.is_array()) return "an array of " + std::to_string(j.size()) + " element(s)";
        if (j.is_object()) return "an object of " + std::to_string(j.size()) + " member(s)";
        return j.type_name();
    }

    void check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> known) const {
        for (auto it = obj.begin(); it != obj.end(); ++it) {
            const std::string& k = it.key();
            if (!k.empty() && k[0] == '_') continue;
            bool ok = false;
            for (const char* n : known) ok = ok || k == n;
            if (!ok) {
                std::string list;
                for (const char* n : known) list += std::string(list.empty() ? "" : ", ") + n;
                fail(join(path, k), "is not a known key (known here: " + list +
                                        "; prefix a key with '_' to make it a comment)");
            }
        }
    }

    const json& object(const json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "must be an object, found " + describe(j));
        return j;
    }

    // read_json already refused numbers beyond double range, so every number here is finite.
    double number(const json& j, const std::string& path, double lo, double hi, bool lo_open = false) const {
        if (!j.is_number()) fail(path, "must be a number, found " + describe(j));
        const double v = j.get<double>();
        if (!std::isfinite(v) || v < lo || v > hi || (lo_open && v == lo)) {
            std::ostringstream s;
            s << "must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "], found " << describe(j);
            fail(path, s.str());
        }
        return v;
    }

    // A float field: the value must survive the conversion. Beyond float range it would load
    // as +-Inf (which the library refuses later, far from the file); a non-zero value that
    // rounds to 0 would silently change meaning (a cell size of 1e-50 becomes 0).
    float real(const json& j, const std::string& path,
               double lo = -std::numeric_limits<float>::max(),
               double hi = std::numeric_limits<float>::max(), bool lo_open = false) const {
        if (j.is_number()) {
            const double v = j.get<double>();
            if (std::fabs(v) > double(std::numeric_limits<float>::max()))
                fail(path, "is beyond float range (magnitude at most 3.40282e+38), found " + describe(j));
            if (v != 0.0 && static_cast<float>(v) == 0.0f)
                fail(path, "is too small for a float (it would round to 0), found " + describe(j));
        }
        return static_cast<float>(number(j, path, lo, hi, lo_open));
    }

    uint32_t u32(const json& j, const std::string& path, uint32_t lo, uint32_t hi) const {
        if (!j.is_number_integer() && !(j.is_number_float() && std::floor(j.get<double>()) == j.get<double>()))
            fail(path, "must be an integer, found " + describe(j));
        const double v = j.get<double>();
        if (v < lo || v > hi)
            fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + describe(j));
        return static_cast<uint32_t>(v);
    }

    vec3f vec3(const json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3) fail(path, "must be an array of 3 numbers, found " + describe(j));
        vec3f v{};
        for (size_t i = 0; i < 3; ++i) v[i] = real(j[i], join(path, i));
        return v;
    }

    const json& required(const json& obj, const std::string& path, const char* key) const {
        auto it = obj.find(key);
        if (it == obj.end()) fail(join(path, key), "is required but missing");
        return *it;
    }

    std::string string(const json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "must be a string, found " + describe(j));
        return j.get<std::string>();
    }
};

} // namespace pfs
