#include "json_read.h"

#include "util.h"

#include <vector>

namespace pfs {

using json = nlohmann::json;

namespace {

// Longest piece of the input quoted back in a message (a 1 MB number stays out of the log).
constexpr size_t kMaxQuoted = 160;

std::string clipped(std::string s) {
    if (s.size() > kMaxQuoted) s = s.substr(0, kMaxQuoted) + "...";
    return s;
}

// Builds the document from nlohmann's SAX events (as its own DOM parser does) while keeping
// the chain of open containers, so a failure can name where it happened.
class TrackingBuilder : public nlohmann::json_sax<json> {
public:
    TrackingBuilder(json& root, size_t max_depth) : root_(root), max_depth_(max_depth) {}

    bool null() override { return put(nullptr); }
    bool boolean(bool v) override { return put(v); }
    bool number_integer(number_integer_t v) override { return put(v); }
    bool number_unsigned(number_unsigned_t v) override { return put(v); }
    bool number_float(number_float_t v, const string_t&) override { return put(v); }
    bool string(string_t& v) override { return put(std::move(v)); }
    bool binary(binary_t&) override { return fail("binary values are not JSON"); }

    bool start_object(std::size_t) override { return open(json::object()); }
    bool key(string_t& k) override {
        open_.back().key = k;
        open_.back().has_key = true;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(json::array()); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t, const std::string& last_token, const nlohmann::detail::exception& ex) override {
        if (ex.id == 406)  // out_of_range.406: strtod gave +-inf
            return fail("number " + clipped(last_token) + " is beyond double range");
        std::string msg = ex.what();
        const size_t close = msg.find("] ");
        if (msg.rfind("[json.exception", 0) == 0 && close != std::string::npos) msg = msg.substr(close + 2);
        return fail("invalid JSON: " + clipped(msg));
    }

    const std::string& pointer() const { return error_pointer_; }
    const std::string& reason() const { return error_reason_; }

private:
    struct Level {
        json* value;
        std::string key;  // current member of an object
        bool has_key = false;
    };

    // Where the value being read now sits: each open container's current member (an array's
    // newest element, or the one about to be appended for the innermost).
    std::string current_pointer() const {
        std::string p;
        for (size_t i = 0; i < open_.size(); ++i) {
            const Level& l = open_[i];
            const bool innermost = i + 1 == open_.size();
            if (l.value->is_array()) {
                const size_t n = l.value->size();
                if (innermost) p = pointer_join(p, std::to_string(n));
                else if (n) p = pointer_join(p, std::to_string(n - 1));
            } else if (l.has_key) {
                p = pointer_join(p, l.key);
            }
        }
        return p;
    }

    bool fail(const std::string& reason) {
        if (error_reason_.empty()) {
            error_pointer_ = current_pointer();
            error_reason_ = reason;
        }
        return false;
    }

    template <class V>
    json* place(V&& v) {
        if (open_.empty()) {
            root_ = json(std::forward<V>(v));
            return &root_;
        }
        json& parent = *open_.back().value;
        if (parent.is_array()) {
            parent.push_back(json(std::forward<V>(v)));
            return &parent.back();
        }
        json& slot = parent[open_.back().key];
        slot = json(std::forward<V>(v));
        return &slot;
    }

    template <class V>
    bool put(V&& v) {
        place(std::forward<V>(v));
        return true;
    }

    bool open(json&& empty) {
        if (open_.size() >= max_depth_)
            return fail("is nested deeper than " + std::to_string(max_depth_) + " levels");
        json* v = place(std::move(empty));
        open_.push_back(Level{v, {}, false});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    json& root_;
    size_t max_depth_;
    std::vector<Level> open_;
    std::string error_pointer_, error_reason_;
};

} // namespace

std::string pointer_join(const std::string& parent, const std::string& key) {
    std::string p = parent + "/";
    for (char c : key) {
        if (c == '~') p += "~0";
        else if (c == '/') p += "~1";
        else p += c;
    }
    return p;
}

std::string pointer_text(const std::string& pointer) { return pointer.empty() ? "(top level)" : pointer; }

json read_json(const std::string& text, const std::string& file, size_t max_depth) {
    json root;
    TrackingBuilder builder(root, max_depth);
    const bool ok = json::sax_parse(text, &builder, json::input_format_t::json, /*strict=*/true,
                                    /*ignore_comments=*/true);
    if (!ok) {
        // A rejected document may be half built; free it here, before the message leaves.
        root = json();
        throw Error(file + ": " + pointer_text(builder.pointer()) + ": " + builder.reason());
    }
    return root;
}

} // namespace pfs
