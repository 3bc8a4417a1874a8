#include "apps/packed_animation.hpp"

#include <limits>
#include <new>

#include <zlib.h>

#include "common/internal_error.hpp"
#include "render/html_text.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

constexpr const char* kDataId = "tf-animation-data";

// The unpacking: base64 to bytes, gunzip, the text parsed as the root's children (an HTML parser
// puts markup set on an <svg> element into the SVG namespace).
constexpr const char* kUnpackHead = R"js((function () {
  "use strict";
  function run() {
)js";
// Around kDataId, so that the script and the element it reads name it once.
constexpr const char* kUnpackTailBeforeId = R"js(  }
  var data = document.getElementById(")js";
constexpr const char* kUnpackTail = R"js(");
  var bytes = Uint8Array.from(atob(data.textContent.trim()), function (c) { return c.charCodeAt(0); });
  new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"))).text().then(function (content) {
    document.querySelector("svg.tf-animation").innerHTML = content;
    data.remove();
    run();
  });
})();
)js";

// RFC 1952 gzip at zlib's best level; the header's time is 0, so the bytes depend on `text` alone.
std::string gzip(const std::string& text) {
    if (text.size() > std::numeric_limits<uInt>::max()) throw InvalidArgument("animation", "is over 4 GB");
    z_stream stream{};
    // 15 + 16: a 32 KB window with a gzip wrapper; 9: zlib's largest memory level, best packing.
    if (deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK) {
        throw std::bad_alloc();
    }
    std::string packed(deflateBound(&stream, static_cast<uLong>(text.size())), '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    stream.avail_in = static_cast<uInt>(text.size());
    stream.next_out = reinterpret_cast<Bytef*>(packed.data());
    stream.avail_out = static_cast<uInt>(packed.size());
    const int result = deflate(&stream, Z_FINISH);
    packed.resize(stream.total_out);
    deflateEnd(&stream);
    if (result != Z_STREAM_END) throw internal_error("zlib did not finish the animation's stream");
    return packed;
}

}  // namespace

PackedAnimation pack_animation(const std::string& svg) {
    const std::size_t open_end = svg.find('>');
    const std::size_t close = svg.rfind("</svg>");
    if (svg.compare(0, 4, "<svg") != 0 || open_end == std::string::npos || close == std::string::npos ||
        close < open_end) {
        throw internal_error("the animation is not one <svg> element");
    }
    PackedAnimation packed;
    packed.root = svg.substr(0, open_end + 1) + svg.substr(close);
    packed.data = std::string("<script type=\"application/gzip\" id=\"") + kDataId + "\">" +
                  base64(gzip(svg.substr(open_end + 1, close - open_end - 1))) + "</script>\n";
    return packed;
}

std::string after_unpacking(const std::string& script) {
    return kUnpackHead + script + kUnpackTailBeforeId + kDataId + kUnpackTail;
}

}  // namespace talkface::detail
