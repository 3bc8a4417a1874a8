// The export writers, one file each (rhubarb_tsv.cpp, rhubarb_json.cpp, ...), found by name in
// export_formats.cpp. Each returns the whole document; none writes a file.
#ifndef TALKFACE_TIMING_EXPORT_WRITERS_HPP
#define TALKFACE_TIMING_EXPORT_WRITERS_HPP

#include <string>
#include <vector>

#include "talkface/timing_formats.hpp"

namespace talkface::detail {

std::string rhubarb_tsv(const ExportInput& input);   // rhubarb_tsv.cpp
std::string rhubarb_json(const ExportInput& input);  // rhubarb_json.cpp
std::string rhubarb_xml(const ExportInput& input);   // rhubarb_xml.cpp
std::string moho_switch(const ExportInput& input);   // moho_switch.cpp
std::string live2d_motion(const ExportInput& input);  // live2d_motion.cpp
std::string textgrid(const Timeline& timeline);       // textgrid.cpp
std::string subrip(const Timeline& timeline);         // subrip.cpp
std::string webvtt(const Timeline& timeline);         // webvtt.cpp

// "a, b, c": format names for messages (export_formats.cpp).
std::string format_list(const std::vector<std::string>& names);

// The recording's path made absolute, as Rhubarb writes its metadata.soundFile.
std::string absolute_audio_path(const std::string& audio_path);

}  // namespace talkface::detail

#endif
