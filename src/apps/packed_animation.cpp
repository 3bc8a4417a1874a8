#include "apps/packed_animation.hpp"

#include <cstdlib>
#include <memory>
#include <new>
#include <utility>

#include <libdeflate.h>

#include "common/internal_error.hpp"
#include "render/html_text.hpp"

namespace talkface::detail {

namespace {

constexpr const char* kDataId = "tf-animation-data";

// Between the animation's content and the still head's in the packed text.
constexpr char kStillSeparator = '\f';

// The unpacking: base64 to bytes, gunzip, the text parsed as the root's children (an HTML parser
// puts markup set on an <svg> element into the SVG namespace); while the reader asks for reduced
// motion, without the pose's animations (class tf-pose), or the still head's content instead. The
// page's script holds the root, never its content, so the content can be swapped under it; the
// root's clock keeps the time.
constexpr const char* kUnpackHead = R"js((function () {
  "use strict";
  function run() {
)js";
// Around kDataId, so that the script and the element it reads name it once.
constexpr const char* kUnpackTailBeforeId = R"js(  }
  var data = document.getElementById(")js";
constexpr const char* kUnpackTail = R"js(");
  var bytes = Uint8Array.from(atob(data.textContent.trim()), function (c) { return c.charCodeAt(0); });
  new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"))).text().then(function (text) {
    var contents = text.split("\f");
    var root = document.querySelector("svg.tf-animation");
    var reduced = window.matchMedia("(prefers-reduced-motion: reduce)");
    function fill() {
      root.innerHTML = contents[reduced.matches ? contents.length - 1 : 0];
      if (reduced.matches) root.querySelectorAll(".tf-pose").forEach(function (pose) { pose.remove(); });
    }
    fill();
    if (contents.length > 1 || contents[0].indexOf("tf-pose") >= 0) reduced.addEventListener("change", fill);
    data.remove();
    run();
  });
})();
)js";

// RFC 1952 gzip by libdeflate at its best level (12), whose near-optimal parsing packs the
// animation 13% smaller than zlib's best (the 3-minute speech's: 258 219 -> 224 490 bytes; 0.18 s
// of CPU where zlib took 0.08 s). The header's time is 0, so the bytes depend on `text` alone.
constexpr int kCompressionLevel = 12;

std::string gzip(const std::string& text) {
    const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
        libdeflate_alloc_compressor(kCompressionLevel), &libdeflate_free_compressor);
    if (!compressor) throw std::bad_alloc();
    std::string packed(libdeflate_gzip_compress_bound(compressor.get(), text.size()), '\0');
    const std::size_t size =
        libdeflate_gzip_compress(compressor.get(), text.data(), text.size(), packed.data(), packed.size());
    // The buffer is as large as libdeflate's bound for the text: it always fits.
    if (size == 0) throw internal_error("libdeflate found no room for the animation's stream");
    packed.resize(size);
    return packed;
}

// An animation document's root element, empty, and its content.
struct SvgParts {
    std::string root;
    std::string content;
};

SvgParts split_root(const std::string& svg) {
    const std::size_t open_end = svg.find('>');
    const std::size_t close = svg.rfind("</svg>");
    if (svg.compare(0, 4, "<svg") != 0 || open_end == std::string::npos || close == std::string::npos ||
        close < open_end) {
        throw internal_error("the animation is not one <svg> element");
    }
    return {svg.substr(0, open_end + 1) + svg.substr(close), svg.substr(open_end + 1, close - open_end - 1)};
}

}  // namespace

PackedAnimation pack_animation(const std::string& svg, const std::string& still_svg) {
    SvgParts parts = split_root(svg);
    std::string text = std::move(parts.content);
    if (!still_svg.empty()) {
        SvgParts still = split_root(still_svg);
        if (still.root != parts.root)
            throw internal_error("the still head's animation has another root element");
        text += kStillSeparator + still.content;
    }
    PackedAnimation packed;
    packed.root = std::move(parts.root);
    packed.data = std::string("<script type=\"application/gzip\" id=\"") + kDataId + "\">" +
                  base64(gzip(text)) + "</script>\n";
    return packed;
}

StageBox root_view_box(const std::string& svg) {
    const std::size_t start = svg.find("viewBox=\"");
    if (start == std::string::npos || start > svg.find('>')) {
        throw internal_error("the animation has no viewBox");
    }
    StageBox box;
    const char* text = svg.c_str() + start + 9;
    double* fields[] = {&box.x, &box.y, &box.width, &box.height};
    for (double* field : fields) {
        char* end = nullptr;
        *field = std::strtod(text, &end);
        text = end;
    }
    return box;
}

std::string after_unpacking(const std::string& script) {
    return kUnpackHead + script + kUnpackTailBeforeId + kDataId + kUnpackTail;
}

}  // namespace talkface::detail
