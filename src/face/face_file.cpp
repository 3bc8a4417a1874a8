// The face file (SPEC pipeline step 1): versioned XML, described in docs/face-format.md.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "common/text_location.hpp"
#include "face/fapu_measure.hpp"
#include "face/point_ids.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr const char* kRootName = "talkface-face";

// The colour attributes of <colors>, named as the FaceColors members.
struct ColourField {
    const char* name;
    Rgb FaceColors::*member;
};
const ColourField kColourFields[] = {{"skin", &FaceColors::skin},
                                     {"hair", &FaceColors::hair},
                                     {"brows", &FaceColors::brows},
                                     {"eye_white", &FaceColors::eye_white},
                                     {"iris", &FaceColors::iris},
                                     {"lips", &FaceColors::lips},
                                     {"mouth_inside", &FaceColors::mouth_inside},
                                     {"outline", &FaceColors::outline}};

// How a FAPU the file leaves out is measured, for the error when the measure is not positive.
const char* measure_formula(std::string_view fapu) {
    static const std::map<std::string_view, const char*> formulas = {{"d", "|EyeballLeft - EyeballRight|"},
                                                                     {"LeftEyeH", "3.4.y - 3.2.y"},
                                                                     {"RightEyeH", "3.3.y - 3.1.y"},
                                                                     {"UpperLipH", "2.2.y - 8.1.y"},
                                                                     {"LowerLipH", "8.2.y - 2.3.y"},
                                                                     {"MNS0", "2.2.y - 9.15.y"},
                                                                     {"MW0", "8.3.x - 8.4.x"},
                                                                     {"JawH", "2.1.y - 8.2.y"},
                                                                     {"r1", "(3.4.y - 3.2.y) / 2"},
                                                                     {"r2", "(3.3.y - 3.1.y) / 2"},
                                                                     {"EyebrowH", "0.12 d"},
                                                                     {"EyebrowH2", "0.09 d"}};
    const auto found = formulas.find(fapu);
    return found == formulas.end() ? "" : found->second;
}

std::string quoted(std::string_view text) {
    return "\"" + std::string(text) + "\"";
}

std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r\n");
    return text.substr(first, last - first + 1);
}

// Reads one face document. pugixml parses a private copy of the text in place, so every name it
// returns points into that copy and its distance from the start is the offset in the original text,
// which gives line and column for any element or attribute (pugixml itself reports none).
class FaceFileReader {
public:
    FaceFileReader(std::string_view text, const std::string& source_name)
        : text_(text), buffer_(text.begin(), text.end()), source_name_(source_name) {}

    FaceModel read(FaceModel face) {
        if (trimmed(text_).empty()) {
            throw ParseError(source_name_, 0, 0, "",
                             "the file is empty; expected a <talkface-face> document");
        }
        pugi::xml_document document;
        const pugi::xml_parse_result parsed = document.load_buffer_inplace(
            buffer_.data(), buffer_.size(), pugi::parse_default, pugi::encoding_utf8);
        if (parsed.status == pugi::status_no_document_element) {
            throw ParseError(source_name_, 1, 1, "",
                             "not an XML file: no element found; expected a <talkface-face> document");
        }
        if (!parsed) {
            const detail::TextLocation where = detail::locate_offset(text_, parsed.offset);
            throw ParseError(source_name_, where.line, where.column, "",
                             std::string("not a well-formed XML file: ") + parsed.description());
        }
        const pugi::xml_node root = document.document_element();
        if (std::string_view(root.name()) != kRootName) {
            fail(root, element_item(root),
                 "expected the root element <talkface-face> (is this a talkface face file?)");
        }
        read_root_attributes(root, face);

        pugi::xml_node colors;
        pugi::xml_node fapus;
        pugi::xml_node points;
        for (pugi::xml_node child : root.children()) {
            check_no_text(child);
            if (child.type() != pugi::node_element) continue;
            const std::string_view name = child.name();
            pugi::xml_node* slot = name == "colors"   ? &colors
                                   : name == "fapus"  ? &fapus
                                   : name == "points" ? &points
                                                      : nullptr;
            if (slot == nullptr) {
                fail(child, element_item(child), "unknown element; expected <colors>, <fapus> and <points>");
            }
            if (*slot) {
                fail(child, element_item(child),
                     "appears twice (first on line " + std::to_string(line_of(*slot)) + ")");
            }
            *slot = child;
        }
        if (!points) fail(root, element_item(root), "has no <points> element; it must list all 72 points");
        if (colors) read_colours(colors, face);
        const std::vector<pugi::xml_node> point_nodes = read_points(points, face);
        check_eyeballs_apart(point_nodes, face);
        read_fapus(fapus, points, face);
        return face;
    }

private:
    [[noreturn]] void fail_at(const char* position, const std::string& item,
                              const std::string& problem) const {
        detail::TextLocation where;
        if (position != nullptr && position >= buffer_.data() &&
            position <= buffer_.data() + buffer_.size()) {
            where = detail::locate_offset(text_, position - buffer_.data());
        }
        throw ParseError(source_name_, where.line, where.column, item, problem);
    }

    // Elements are located at their '<'; pugixml's name pointer is one past it.
    [[noreturn]] void fail(pugi::xml_node node, const std::string& item, const std::string& problem) const {
        fail_at(node.name() - 1, item, problem);
    }

    [[noreturn]] void fail(pugi::xml_attribute attribute, const std::string& item,
                           const std::string& problem) const {
        fail_at(attribute.name(), item, problem);
    }

    int line_of(pugi::xml_node node) const {
        return detail::locate_offset(text_, node.name() - 1 - buffer_.data()).line;
    }

    static std::string element_item(pugi::xml_node node) {
        return "element <" + std::string(node.name()) + ">";
    }

    void check_no_text(pugi::xml_node node) const {
        if ((node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) &&
            !trimmed(node.value()).empty()) {
            fail_at(node.value(), "",
                    "unexpected text " + quoted(trimmed(node.value())) +
                        "; a face file holds elements and attributes only");
        }
    }

    void read_root_attributes(pugi::xml_node root, FaceModel& face) const {
        bool has_version = false;
        for (pugi::xml_attribute attribute : root.attributes()) {
            const std::string_view name = attribute.name();
            if (name == "version") {
                has_version = true;
                check_version(attribute);
            } else if (name == "name") {
                face.set_name(attribute.value());
            } else {
                fail(attribute, element_item(root),
                     "unknown attribute " + std::string(name) + "; expected version and name");
            }
        }
        if (!has_version) {
            fail(root, element_item(root),
                 "missing attribute version (this library reads versions up to " +
                     std::to_string(FaceModel::kFileFormatVersion) + ")");
        }
    }

    void check_version(pugi::xml_attribute attribute) const {
        const std::string_view text = trimmed(attribute.value());
        int version = 0;
        const auto result = std::from_chars(text.data(), text.data() + text.size(), version);
        const std::string supported =
            "this library reads versions up to " + std::to_string(FaceModel::kFileFormatVersion);
        if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size()) {
            fail(attribute, "attribute version",
                 "expected a whole number, found " + quoted(attribute.value()) + "; " + supported);
        }
        if (version > FaceModel::kFileFormatVersion) {
            fail(attribute, "attribute version",
                 "version " + std::to_string(version) + " is newer than this library reads (up to " +
                     std::to_string(FaceModel::kFileFormatVersion) + "); update talkface");
        }
        if (version < 1) {
            fail(attribute, "attribute version",
                 "unknown version " + std::to_string(version) + "; " + supported);
        }
    }

    void check_no_children(pugi::xml_node node) const {
        for (pugi::xml_node child : node.children()) {
            check_no_text(child);
            if (child.type() == pugi::node_element) {
                fail(child, element_item(child), "unexpected inside <" + std::string(node.name()) + ">");
            }
        }
    }

    void read_colours(pugi::xml_node colors, FaceModel& face) const {
        check_no_children(colors);
        FaceColors colours;  // attributes left out keep the FaceColors defaults
        for (pugi::xml_attribute attribute : colors.attributes()) {
            const std::string_view name = attribute.name();
            const auto field = std::find_if(std::begin(kColourFields), std::end(kColourFields),
                                            [&](const ColourField& f) { return name == f.name; });
            if (field == std::end(kColourFields)) {
                fail(attribute, "colour " + quoted(name),
                     "unknown colour; expected skin, hair, brows, eye_white, iris, lips, mouth_inside, "
                     "outline");
            }
            try {
                colours.*(field->member) = rgb_from_hex(trimmed(attribute.value()));
            } catch (const InvalidArgument&) {
                fail(attribute, "colour " + quoted(name),
                     "expected #rrggbb or #rgb, found " + quoted(attribute.value()));
            }
        }
        face.set_colors(colours);
    }

    double read_number(pugi::xml_attribute attribute, const std::string& item) const {
        const std::string what = "attribute " + std::string(attribute.name());
        const auto value = detail::parse_double(trimmed(attribute.value()));
        if (!value) {
            fail(attribute, item, what + ": expected a number, found " + quoted(attribute.value()));
        }
        if (!std::isfinite(*value)) {
            fail(attribute, item, what + ": expected a finite number, found " + quoted(attribute.value()));
        }
        if (std::abs(*value) > FaceModel::kMaxCoordinatePx) {
            fail(attribute, item, what + ": " + quoted(attribute.value()) + " is beyond +-1e6 px");
        }
        return *value;
    }

    // Returns each point's element, in FaceModel::point_ids() order.
    std::vector<pugi::xml_node> read_points(pugi::xml_node points, FaceModel& face) const {
        for (pugi::xml_attribute attribute : points.attributes()) {
            fail(attribute, "element <points>", "unexpected attribute " + std::string(attribute.name()));
        }
        std::vector<pugi::xml_node> seen(FaceModel::kPointCount);
        for (pugi::xml_node node : points.children()) {
            check_no_text(node);
            if (node.type() != pugi::node_element) continue;
            if (std::string_view(node.name()) != "point") {
                fail(node, element_item(node), "unexpected inside <points>; expected <point>");
            }
            check_no_children(node);
            read_point(node, seen, face);
        }
        std::vector<std::string> missing;
        for (std::size_t i = 0; i < seen.size(); ++i) {
            if (!seen[i]) missing.push_back(quoted(FaceModel::point_ids()[i]));
        }
        if (!missing.empty()) {
            std::string list;
            for (const std::string& id : missing) list += (list.empty() ? "" : ", ") + id;
            fail(points, "element <points>",
                 "missing " + std::to_string(missing.size()) +
                     (missing.size() == 1 ? " point: " : " points: ") + list +
                     "; a face lists all 72 points");
        }
        return seen;
    }

    // Lifting and gaze divide by the eyeball distance, whatever the file says d is.
    void check_eyeballs_apart(const std::vector<pugi::xml_node>& point_nodes, const FaceModel& face) const {
        if (detail::measured_fapu(face, "d") > 0.0) return;
        const Point2 right = face.point("EyeballRight");
        fail(point_nodes[*detail::point_index("EyeballRight")], "point \"EyeballRight\"",
             "at the same place as EyeballLeft (" + detail::format_shortest(right.x) + ", " +
                 detail::format_shortest(right.y) +
                 "), so the eye distance d would be 0; the eyeball "
                 "centres must be apart");
    }

    void read_point(pugi::xml_node node, std::vector<pugi::xml_node>& seen, FaceModel& face) const {
        const pugi::xml_attribute id_attribute = node.attribute("id");
        if (!id_attribute) fail(node, element_item(node), "missing attribute id");
        const std::string id = std::string(trimmed(id_attribute.value()));
        const std::string item = "point " + quoted(id);
        const auto index = detail::point_index(id);
        if (!index) {
            fail(id_attribute, item,
                 "unknown point id; expected one of the 72 ids of docs/face-format.md (hair.1 .. hair.23, "
                 "11.1, ..., EyeballRight)");
        }
        if (seen[*index]) {
            fail(node, item,
                 "defined twice, on lines " + std::to_string(line_of(seen[*index])) + " and " +
                     std::to_string(line_of(node)));
        }
        seen[*index] = node;
        pugi::xml_attribute x;
        pugi::xml_attribute y;
        for (pugi::xml_attribute attribute : node.attributes()) {
            const std::string_view name = attribute.name();
            if (name == "x") {
                x = attribute;
            } else if (name == "y") {
                y = attribute;
            } else if (name != "id") {
                fail(attribute, item, "unknown attribute " + std::string(name) + "; expected id, x and y");
            }
        }
        if (!x || !y) {
            const std::string found = x ? "found only x" : y ? "found only y" : "found neither";
            fail(node, item, "expected attributes x and y, " + found);
        }
        face.set_point(id, {read_number(x, item), read_number(y, item)});
    }

    void read_fapus(pugi::xml_node fapus, pugi::xml_node points, FaceModel& face) const {
        std::vector<bool> given(FaceModel::kFapuCount, false);
        if (fapus) {
            check_no_children(fapus);
            for (pugi::xml_attribute attribute : fapus.attributes()) {
                const std::string name = attribute.name();
                const std::string item = "FAPU " + quoted(name);
                const auto index = detail::fapu_index(name);
                if (!index) {
                    fail(attribute, item,
                         "unknown FAPU; expected d, EyebrowH, EyebrowH2, LeftEyeH, RightEyeH, UpperLipH, "
                         "LowerLipH, MNS0, MW0, JawH, r1, r2");
                }
                const double value = read_number(attribute, item);
                if (value <= 0.0)
                    fail(attribute, item, "must be positive, found " + quoted(attribute.value()));
                face.set_fapu(name, value);
                given[*index] = true;
            }
        }
        for (std::size_t i = 0; i < FaceModel::kFapuCount; ++i) {
            if (given[i]) continue;
            const std::string& name = FaceModel::fapu_names()[i];
            const double measured = detail::measured_fapu(face, name);
            if (!(std::isfinite(measured) && measured > 0.0)) {
                fail(fapus ? fapus : points, "FAPU " + quoted(name),
                     "not given, and measuring it from the points (" + std::string(measure_formula(name)) +
                         ") gives " + detail::format_shortest(measured) +
                         " px, which is not positive; give it in <fapus> or fix the points");
            }
            face.set_fapu(name, measured);
        }
    }

    std::string_view text_;
    std::vector<char> buffer_;
    const std::string& source_name_;
};

}  // namespace

FaceModel FaceModel::from_xml(std::string_view xml, const std::string& source_name) {
    return FaceFileReader(xml, source_name).read(FaceModel(Blank{}));
}

FaceModel FaceModel::load(const std::string& path) {
    const std::string text = detail::read_file(path);
    return from_xml(text, path);
}

std::string FaceModel::to_xml() const {
    pugi::xml_document document;
    pugi::xml_node declaration = document.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";
    document.append_child(pugi::node_comment)
        .set_value(" talkface face file; the format is described in docs/face-format.md ");
    pugi::xml_node root = document.append_child(kRootName);
    root.append_attribute("version") = kFileFormatVersion;
    root.append_attribute("name") = name_.c_str();

    pugi::xml_node colors = root.append_child("colors");
    for (const ColourField& field : kColourFields) {
        colors.append_attribute(field.name) = to_hex(colors_.*(field.member)).c_str();
    }
    pugi::xml_node fapus = root.append_child("fapus");
    for (std::size_t i = 0; i < kFapuCount; ++i) {
        fapus.append_attribute(fapu_names()[i].c_str()) = detail::format_shortest(fapus_[i]).c_str();
    }
    pugi::xml_node points = root.append_child("points");
    for (std::size_t i = 0; i < kPointCount; ++i) {
        pugi::xml_node point = points.append_child("point");
        point.append_attribute("id") = point_ids()[i].c_str();
        point.append_attribute("x") = detail::format_shortest(points_[i].x).c_str();
        point.append_attribute("y") = detail::format_shortest(points_[i].y).c_str();
    }
    std::ostringstream out;
    document.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
}

void FaceModel::save(const std::string& path) const {
    detail::write_file_atomically(path, to_xml());
}

}  // namespace v0
}  // namespace talkface
