// Face from a photo: photo files in (PNG, JPEG) and the debug overlay out (PNG), through libpng and
// libjpeg-turbo. OpenCV's imgcodecs would do both in one call each, but it links GDAL and some 140
// shared libraries whose loading cost every program linking talkface 0.12 s at start-up; libpng and
// libjpeg are two small libraries (and dlib, when built in, loads them anyway).
#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>  // before jpeglib.h, which uses FILE without declaring it
#include <cstring>
#include <memory>
#include <string>

#include <jpeglib.h>
#include <jerror.h>  // after jpeglib.h: the JWRN_ codes
#include <png.h>

#include "common/internal_error.hpp"
#include "photo/photo_internal.hpp"
#include "talkface/errors.hpp"

namespace talkface::photo {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

void check_pixel_count(std::uint64_t width, std::uint64_t height, const std::string& path) {
    const std::uint64_t pixels = width * height;
    if (pixels > kMaxPhotoPixels) {
        throw FileError(path, std::to_string(width) + " x " + std::to_string(height) + " pixels (" +
                                  std::to_string(pixels / 1000000) + " megapixels) is more than the " +
                                  std::to_string(kMaxPhotoPixels / 1000000) +
                                  " megapixels talkface reads; scale the photo down");
    }
}

// The formats people try that talkface does not read, named by their first bytes so that the error
// says what the file is instead of only what it is not.
const char* other_format(const unsigned char* head, std::size_t size) {
    auto starts = [&](const char* magic, std::size_t at = 0) {
        const std::size_t length = std::strlen(magic);
        return size >= at + length && std::memcmp(head + at, magic, length) == 0;
    };
    if (starts("BM")) return "a BMP image";
    if (starts("GIF8")) return "a GIF image";
    if (starts("II*") || (size >= 4 && std::memcmp(head, "MM\0*", 4) == 0)) return "a TIFF image";
    if (starts("RIFF") && starts("WEBP", 8)) return "a WebP image";
    if (starts("ftypheic", 4) || starts("ftypheix", 4) || starts("ftypmif1", 4)) return "a HEIF image";
    if (starts("ftypavif", 4)) return "an AVIF image";
    if (size >= 2 && head[0] == 'P' && head[1] >= '1' && head[1] <= '6') return "a PNM image";
    return nullptr;
}

// --- PNG: libpng's simplified API reports errors in png_image::message, without setjmp ----------

[[noreturn]] void fail_png(std::FILE* file, const png_image& image, const std::string& path) {
    const std::string reason = std::feof(file) ? "the file ends before the image does (truncated)" : image.message;
    throw FileError(path, "broken PNG: " + reason);
}

cv::Mat read_png(std::FILE* file, const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&image, file)) fail_png(file, image, path);
    const std::unique_ptr<png_image, void (*)(png_imagep)> release(&image, png_image_free);
    check_pixel_count(image.width, image.height, path);
    image.format = PNG_FORMAT_BGR;
    cv::Mat bgr(static_cast<int>(image.height), static_cast<int>(image.width), CV_8UC3);
    // A transparent background is read as white, as a viewer shows it on a page.
    const png_color white{255, 255, 255};
    if (!png_image_finish_read(&image, &white, bgr.data, static_cast<png_int_32>(bgr.step[0]), nullptr)) {
        fail_png(file, image, path);
    }
    return bgr;
}

// --- JPEG: libjpeg reports errors through a callback that must not return -----------------------

// Lives in read_jpeg's frame, not decode_jpeg's: longjmp back into decode_jpeg leaves that frame's
// locals indeterminate, and no C++ object with a destructor may live there.
struct JpegDecoder {
    jpeg_decompress_struct info;
    jpeg_error_mgr errors;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    std::uint64_t width, height;
    bool is_cmyk;
    int orientation;
};

[[noreturn]] void on_jpeg_error(j_common_ptr info) {
    // client_data points at the JpegDecoder (set in decode_jpeg).
    auto* decoder = static_cast<JpegDecoder*>(info->client_data);
    (*info->err->format_message)(info, decoder->message);
    std::longjmp(decoder->jump, 1);
}

// libjpeg only warns about corrupt data (a truncated file, a bad Huffman code) and fills the rest of
// the picture with grey; a face extracted from that would be wrong without a word, so every warning
// but padding between markers (which some cameras write, harmlessly) ends the decoding.
void on_jpeg_message(j_common_ptr info, int level) {
    if (level < 0 && info->err->msg_code != JWRN_EXTRANEOUS_DATA) on_jpeg_error(info);
}

std::uint32_t read_exif_number(const JOCTET* at, bool big_endian, int bytes) {
    std::uint32_t value = 0;
    for (int k = 0; k < bytes; ++k) {
        const int shift = 8 * (big_endian ? bytes - 1 - k : k);
        value |= static_cast<std::uint32_t>(at[k]) << shift;
    }
    return value;
}

// The EXIF Orientation tag (0x0112 in IFD0) of an APP1 marker, 1 (as stored) when absent: phone
// cameras store portraits sideways and say so here.
int exif_orientation(jpeg_saved_marker_ptr markers) {
    for (jpeg_saved_marker_ptr marker = markers; marker != nullptr; marker = marker->next) {
        const JOCTET* data = marker->data;
        const std::size_t size = marker->data_length;
        if (marker->marker != JPEG_APP0 + 1 || size < 14 || std::memcmp(data, "Exif\0\0", 6) != 0) continue;
        const JOCTET* tiff = data + 6;
        const std::size_t tiff_size = size - 6;
        const bool big_endian = tiff[0] == 'M';
        const std::uint32_t ifd = read_exif_number(tiff + 4, big_endian, 4);
        if (std::uint64_t{ifd} + 2 > tiff_size) return 1;
        const std::uint32_t entries = read_exif_number(tiff + ifd, big_endian, 2);
        for (std::uint32_t k = 0; k < entries && ifd + 2 + 12 * (std::uint64_t{k} + 1) <= tiff_size; ++k) {
            const JOCTET* entry = tiff + ifd + 2 + 12 * k;
            if (read_exif_number(entry, big_endian, 2) == 0x0112) {
                const int value = static_cast<int>(read_exif_number(entry + 8, big_endian, 2));
                return value >= 1 && value <= 8 ? value : 1;
            }
        }
    }
    return 1;
}

// Decodes into `bgr`, or stops after the header (bgr left empty) for a photo too large or in CMYK;
// false with decoder.message when libjpeg fails.
bool decode_jpeg(std::FILE* file, JpegDecoder& decoder, cv::Mat& bgr) {
    jpeg_decompress_struct& info = decoder.info;
    info.err = jpeg_std_error(&decoder.errors);
    decoder.errors.error_exit = on_jpeg_error;
    decoder.errors.emit_message = on_jpeg_message;
    if (setjmp(decoder.jump)) {
        jpeg_destroy_decompress(&decoder.info);
        return false;
    }
    jpeg_create_decompress(&info);
    info.client_data = &decoder;
    jpeg_stdio_src(&info, file);
    jpeg_save_markers(&info, JPEG_APP0 + 1, 0xFFFF);
    jpeg_read_header(&info, TRUE);
    decoder.width = info.image_width;
    decoder.height = info.image_height;
    decoder.is_cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
    decoder.orientation = exif_orientation(info.marker_list);
    if (decoder.width * decoder.height <= kMaxPhotoPixels && !decoder.is_cmyk) {
        info.out_color_space = JCS_EXT_BGR;
        jpeg_start_decompress(&info);
        bgr.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width), CV_8UC3);
        while (info.output_scanline < info.output_height) {
            JSAMPROW row = bgr.ptr<JSAMPLE>(static_cast<int>(info.output_scanline));
            jpeg_read_scanlines(&info, &row, 1);
        }
        jpeg_finish_decompress(&info);
    }
    jpeg_destroy_decompress(&info);
    return true;
}

// EXIF orientations 2..8 as flips and transposes (the mapping OpenCV's imread applies).
cv::Mat apply_orientation(cv::Mat bgr, int orientation) {
    if (orientation >= 5) cv::transpose(bgr, bgr);
    switch (orientation) {
        case 2: case 6: cv::flip(bgr, bgr, 1); break;
        case 3: case 7: cv::flip(bgr, bgr, -1); break;
        case 4: case 8: cv::flip(bgr, bgr, 0); break;
        default: break;
    }
    return bgr;
}

cv::Mat read_jpeg(std::FILE* file, const std::string& path) {
    JpegDecoder decoder{};
    cv::Mat bgr;
    if (!decode_jpeg(file, decoder, bgr)) {
        const std::string reason = decoder.errors.msg_code == JWRN_JPEG_EOF
                                       ? "the file ends before the image does (truncated)"
                                       : decoder.message;
        throw FileError(path, "broken JPEG: " + reason);
    }
    check_pixel_count(decoder.width, decoder.height, path);
    if (decoder.is_cmyk) {
        throw FileError(path, "a CMYK JPEG (made for print); talkface reads RGB and greyscale JPEGs: save the "
                              "photo as RGB");
    }
    return apply_orientation(bgr, decoder.orientation);
}

}  // namespace

cv::Mat read_photo_file(const std::string& path) {
    const File file(std::fopen(path.c_str(), "rb"));
    if (!file) throw FileError(path, std::strerror(errno));
    unsigned char head[16] = {};
    const std::size_t size = std::fread(head, 1, sizeof head, file.get());
    if (std::ferror(file.get())) throw FileError(path, std::strerror(errno));
    if (size == 0) throw FileError(path, "the file is empty; expected a PNG or JPEG photo");
    std::rewind(file.get());
    if (size >= 8 && png_sig_cmp(head, 0, 8) == 0) return read_png(file.get(), path);
    if (size >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF) return read_jpeg(file.get(), path);
    if (const char* format = other_format(head, size)) {
        throw FileError(path, std::string(format) + "; talkface reads PNG and JPEG photos: convert it to one of them");
    }
    throw FileError(path, "not a PNG or JPEG photo (the file starts with neither's signature)");
}

std::string encode_png(const cv::Mat& bgr) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(bgr.cols);
    image.height = static_cast<png_uint_32>(bgr.rows);
    image.format = PNG_FORMAT_BGR;
    const auto stride = static_cast<png_int_32>(bgr.step[0]);
    png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(image);
    std::string png(size, '\0');
    if (!png_image_write_to_memory(&image, png.data(), &size, 0, bgr.data, stride, nullptr)) {
        throw detail::internal_error(std::string("libpng could not encode the overlay: ") + image.message);
    }
    png.resize(size);
    return png;
}

}  // namespace talkface::photo
