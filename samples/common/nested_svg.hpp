// Placing whole talkface documents inside a bigger SVG (contact sheets): each document becomes a
// nested <svg> element, so the sheet stays self-contained and every cell keeps its own viewBox.
#ifndef TALKFACE_SAMPLES_NESTED_SVG_HPP
#define TALKFACE_SAMPLES_NESTED_SVG_HPP

#include <locale>
#include <regex>
#include <sstream>
#include <string>

namespace talkface_samples {

// Where a cell goes in the sheet, and which part of the document it shows.
struct Cell {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
    std::string view_box;  // empty: the document's own viewBox
};

// A number as SVG writes it, whatever the C++ locale.
inline std::string svg_number(double value) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << value;
    return out.str();
}

// `document` (what SvgAnimator::render_svg returns) as a nested <svg> at `cell`. Every id and every
// url(#...) and href="#..." reference gets `id_prefix`, since the same ids repeat in every cell of a
// sheet.
inline std::string nest_svg(const std::string& document, const Cell& cell, const std::string& id_prefix) {
    std::string body = std::regex_replace(document, std::regex(R"(<\?xml[^>]*\?>\s*)"), "");
    body = std::regex_replace(body, std::regex(R"( id=")"), " id=\"" + id_prefix);
    body = std::regex_replace(body, std::regex(R"(url\(#)"), "url(#" + id_prefix);
    body = std::regex_replace(body, std::regex(R"(href="#)"), "href=\"#" + id_prefix);

    const std::size_t root_end = body.find('>');
    std::string root = body.substr(0, root_end);
    root = std::regex_replace(root, std::regex(R"( (width|height)="[^"]*")"), "");
    if (!cell.view_box.empty()) {
        root = std::regex_replace(root, std::regex(R"(viewBox="[^"]*")"), "viewBox=\"" + cell.view_box + "\"");
    }
    root += " x=\"" + svg_number(cell.x) + "\" y=\"" + svg_number(cell.y) + "\" width=\"" +
            svg_number(cell.width) + "\" height=\"" + svg_number(cell.height) + "\"";
    return root + body.substr(root_end);
}

// Text safe inside an SVG element or attribute.
inline std::string escape_xml(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        switch (c) {
            case '&': escaped += "&amp;"; break;
            case '<': escaped += "&lt;"; break;
            case '>': escaped += "&gt;"; break;
            case '"': escaped += "&quot;"; break;
            case '\'': escaped += "&apos;"; break;
            default: escaped += c;
        }
    }
    return escaped;
}

}  // namespace talkface_samples

#endif
