// The font stacks of the pages: each names the Chinese fonts that come with the common systems,
// so a page shows real characters wherever it is opened, not only where Noto CJK is installed.
#ifndef TALKFACE_APPS_PAGE_FONTS_HPP
#define TALKFACE_APPS_PAGE_FONTS_HPP

namespace talkface::detail {

// Sans-serif, for headings, captions and controls. In order: macOS and iOS (PingFang, Hiragino),
// Windows (Microsoft JhengHei for Traditional, YaHei for Simplified), Linux and Android (Noto Sans
// CJK as fonts-noto-cjk and Android name it, Source Han Sans, WenQuanYi, Droid Sans Fallback), then
// the generic family, through which each browser's own CJK fallback still finds a font.
// system-ui leads so that Latin text keeps the system's face.
constexpr const char* kSansFonts =
    "system-ui,-apple-system,\"PingFang TC\",\"PingFang SC\",\"Hiragino Sans\",\"Hiragino Sans GB\","
    "\"Microsoft JhengHei\",\"Microsoft YaHei\",\"Noto Sans CJK TC\",\"Noto Sans CJK SC\",\"Noto Sans TC\","
    "\"Noto Sans SC\",\"Source Han Sans TC\",\"Source Han Sans SC\",\"WenQuanYi Micro Hei\","
    "\"Droid Sans Fallback\",sans-serif";

// Serif (Ming / Song), for the audio book's text: macOS and iOS (Songti), Windows (PMingLiU,
// SimSun), Linux (Noto Serif CJK from fonts-noto-cjk, Source Han Serif, AR PL UMing), then the
// sans-serif stack: Android and many Linux systems ship no CJK serif, and a sans CJK font reads
// better than the boxes or the odd fallback a bare "serif" can give there.
constexpr const char* kSerifFonts =
    "\"Songti TC\",\"Songti SC\",\"PMingLiU\",\"MingLiU\",\"SimSun\",\"Noto Serif CJK TC\",\"Noto Serif CJK SC\","
    "\"Noto Serif TC\",\"Noto Serif SC\",\"Source Han Serif TC\",\"Source Han Serif SC\",\"AR PL UMing TW\","
    "\"PingFang TC\",\"PingFang SC\",\"Microsoft JhengHei\",\"Microsoft YaHei\",\"Noto Sans CJK TC\","
    "\"Noto Sans CJK SC\",\"Droid Sans Fallback\",serif";

}  // namespace talkface::detail

#endif
