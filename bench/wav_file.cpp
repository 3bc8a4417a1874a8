#include "wav_file.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace talkface_bench {

namespace {

void put_u32(std::string& out, std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) out += static_cast<char>((value >> shift) & 0xffu);
}

void put_u16(std::string& out, std::uint16_t value) {
    out += static_cast<char>(value & 0xffu);
    out += static_cast<char>((value >> 8) & 0xffu);
}

std::uint32_t get_u32(const std::string& data, std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 4; i > 0; --i) value = (value << 8) | static_cast<unsigned char>(data[at + i - 1]);
    return value;
}

std::uint16_t get_u16(const std::string& data, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(data[at]) |
                                      (static_cast<unsigned char>(data[at + 1]) << 8));
}

}  // namespace

void write_wav(const std::string& path, const MonoAudio& audio) {
    const auto data_bytes = static_cast<std::uint32_t>(audio.samples.size() * 2);
    const auto rate = static_cast<std::uint32_t>(audio.sample_rate_hz);
    std::string out = "RIFF";
    put_u32(out, 36 + data_bytes);
    out += "WAVEfmt ";
    put_u32(out, 16);
    put_u16(out, 1);  // PCM
    put_u16(out, 1);  // mono
    put_u32(out, rate);
    put_u32(out, rate * 2);
    put_u16(out, 2);
    put_u16(out, 16);
    out += "data";
    put_u32(out, data_bytes);
    out.reserve(out.size() + data_bytes);
    for (float sample : audio.samples) {
        const double scaled = std::round(static_cast<double>(sample) * 32768.0);
        const double clipped = scaled > 32767.0 ? 32767.0 : (scaled < -32768.0 ? -32768.0 : scaled);
        put_u16(out, static_cast<std::uint16_t>(static_cast<std::int16_t>(clipped)));
    }
    std::ofstream file(path, std::ios::binary);
    file.write(out.data(), static_cast<std::streamsize>(out.size()));
    if (!file) throw std::runtime_error(path + ": cannot write");
}

MonoAudio read_wav(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (data.size() < 12 || data.compare(0, 4, "RIFF") != 0 || data.compare(8, 4, "WAVE") != 0)
        throw std::runtime_error(path + ": not a WAV file");
    MonoAudio audio;
    bool format_ok = false;
    for (std::size_t at = 12; at + 8 <= data.size();) {
        const std::string id = data.substr(at, 4);
        const std::size_t size = get_u32(data, at + 4);
        const std::size_t body = at + 8;
        if (body + size > data.size()) throw std::runtime_error(path + ": truncated chunk \"" + id + "\"");
        if (id == "fmt ") {
            const std::uint16_t tag = get_u16(data, body);
            format_ok = (tag == 1 || tag == 0xfffe) && get_u16(data, body + 2) == 1 && get_u16(data, body + 14) == 16;
            audio.sample_rate_hz = static_cast<int>(get_u32(data, body + 4));
        } else if (id == "data") {
            if (!format_ok) throw std::runtime_error(path + ": not mono 16-bit PCM");
            audio.samples.resize(size / 2);
            for (std::size_t i = 0; i < audio.samples.size(); ++i)
                audio.samples[i] = static_cast<float>(static_cast<std::int16_t>(get_u16(data, body + 2 * i))) / 32768.0f;
            return audio;
        }
        at = body + size + (size & 1u);
    }
    throw std::runtime_error(path + ": no data chunk");
}

}  // namespace talkface_bench
