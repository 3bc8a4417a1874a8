// Audio in, one block at a time, mixed down to mono: from a file through libsndfile (WAV, Ogg) or
// FFmpeg (FLAC, MP3, AAC/M4A, Opus, a video's sound track, an Ogg file with a damaged page), or
// from samples the caller holds.
// Nothing here keeps the whole signal (the memory target of issue #4).
#ifndef TALKFACE_AUDIO_AUDIO_SOURCE_HPP
#define TALKFACE_AUDIO_AUDIO_SOURCE_HPP

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "talkface/speech_aligner.hpp"

namespace talkface::detail {

// Mixes frames of interleaved channels down to one, as every reader does. Channels are averaged,
// but a channel that runs against the first one (a stereo file with one side's polarity inverted,
// as a miswired microphone or a "wide" effect leaves it) is turned over before it is added: the
// plain average of a voice and its inverse is nothing, and the recording read as silent. Whether a
// channel runs against the first is judged on everything mixed so far (their normalised
// correlation below -kOppositeCorrelation turns it over; above +kOppositeCorrelation turns it back;
// not before kFramesBeforeJudging frames), so the choice settles at the first second of speech and
// a block's size never changes it. A file
// of one channel, or of channels that agree, mixes exactly as the plain average.
class ChannelMixer {
public:
    // `mono[i]` gets the mix of frame i of `interleaved` (`frames` frames of `channels` samples).
    void mix(const float* interleaved, std::size_t frames, std::size_t channels, float* mono);

private:
    // mix() for two channels.
    void mix_stereo(const float* interleaved, std::size_t frames, float* mono);
    // Sums over every frame mixed: the first channel's energy, each channel's energy and its
    // product with the first. Doubles: an hour at 48 kHz is 1.7e8 products.
    double first_energy_ = 0.0;
    std::size_t frames_mixed_ = 0;
    std::vector<double> energy_;
    std::vector<double> with_first_;
    std::vector<float> sign_;
};

// A stretch of a recording its reader could not decode because the file is damaged there (a packet
// the decoder refused as invalid, an Ogg page or a FLAC frame that failed its check, a Matroska
// cluster the demuxer skipped) and read as silence in its place, in seconds from the start.
struct LostAudio {
    double start_s = 0.0;
    double end_s = 0.0;
};

// A stretch of a recording its codec marks as a pause with no sound to decode, read as silence in
// its place, in seconds from the start: the frames an AMR phone sends while its voice detector
// hears no speech (discontinuous transmission: a comfort-noise description, or no data), which
// this FFmpeg does not decode. The file is whole there: its zeros are the pause the phone heard,
// not sound lost (a dropout, dropout_finder.hpp).
struct CodecPause {
    double start_s = 0.0;
    double end_s = 0.0;
};

// A stretch of a PCM recording whose sound is cut off mid-wave to exact zeros, in seconds from the
// start: an editor's silence over a word, or a block of the file's bytes zeroed (pcm_damage.hpp).
// A note (notes()) names them all; the aligner names no silenced word there again.
struct CutToZeros {
    double start_s = 0.0;
    double end_s = 0.0;
};

// The seconds of sound the stretches hold together.
double lost_seconds(const std::vector<LostAudio>& lost);

// "3.360 s of its sound could not be decoded, at 6.619-9.979 s" (the first three stretches, then
// how many more): what a message says of a damaged file's lost sound. Empty if none was lost.
std::string describe_lost_audio(const std::vector<LostAudio>& lost);

// "300 of its 49448 samples are not numbers (NaN or infinite), the first at 0.773 s: read as
// silence there; ...": AudioSource's note on the `non_finite` of `total` frames it read as 0, the
// first `first_s` from the start; where every frame was one, that none is a number.
std::string describe_non_finite_samples(std::size_t non_finite, std::size_t total, double first_s);

class AudioSource {
public:
    virtual ~AudioSource() = default;
    // Fills `mono` with up to `max_frames` frames (channels averaged); 0 at the end. A sample that
    // is not a number (NaN or an infinity: a damaged stream, a float WAV or a caller's array with a
    // stray one) reads as 0, as a player plays it: every reader of audio (the features, the plot,
    // the page's and the video's sound) gets finite samples, and one such sample cannot turn the
    // features of the rest of the recording into NaN. At the end, a note (notes()) says how many
    // there were and where the first was, so that a reading that finds them says so once.
    // \throws talkface::FileError when the data ends before the header said it would (a WAV's data
    //         size, a container's exact length for its sound track: MP4, a LAME-tagged MP3, FLAC).
    // \throws talkface::ParseError for a sample past kMostSampleMagnitude, named with its time.
    std::size_t read(float* mono, std::size_t max_frames);
    // Moves the reading on to `frame` (counted from the start, past every frame read so far)
    // without decoding what lies between, where the reader can go there straight (libsndfile's
    // sf_seek in a file it can seek in; FFmpeg's seek and a decode to the exact sample, in a file
    // whose timestamps place one, ffmpeg_source.cpp); false where it cannot, the reading left
    // where it was. A reading that passes hours of digital silence this way takes no time for
    // them; what it passes is not read, so its samples that are not numbers and the stretches of it
    // lost to damage are known only where an earlier reading found them (take_first_reading).
    bool skip_to(std::size_t frame);
    // What a reading found as far as it read: its samples that are not numbers and the stretches
    // it read as silence because the file is damaged there. Copied out (first_reading), so that
    // the reading can be let go before the next one is opened: two openings of an MP4 held its
    // index twice.
    struct FirstReading {
        std::size_t frames_read = 0;
        std::size_t non_finite_frames = 0;
        std::size_t first_non_finite_frame = 0;
        std::vector<LostAudio> lost_audio;
    };
    FirstReading first_reading() const;
    // Takes over what an earlier reading of the same recording from its start (read() only) found,
    // before this reading reads anything; from then on this reading counts and notes only what
    // lies past where the earlier one stopped. read()'s note and lost_audio() then name them all,
    // though this reading skip_to()s past the silence the earlier one read them in (a float file
    // NaN there; a lost Matroska cluster or MP3 frames there, whose sound may have been speech the
    // user should know is gone).
    void take_first_reading(FirstReading earlier);
    virtual int sample_rate_hz() const = 0;
    // Frames the source says it has; progress is measured against it. For what FFmpeg reads it is
    // the container's estimate, and read() goes on to the real end.
    virtual std::size_t frame_count() const = 0;
    // Names the audio in messages: the path, or "audio" for samples in memory.
    virtual const std::string& name() const = 0;
    // The stretches read as silence because the file is damaged there, in order, as far as read.
    const std::vector<LostAudio>& lost_audio() const { return lost_audio_; }
    // The stretches read as silence where the codec marks a pause, in order, as far as read.
    const std::vector<CodecPause>& codec_pauses() const { return codec_pauses_; }
    // The stretches cut off mid-wave to exact zeros, in order, once the reading has ended.
    const std::vector<CutToZeros>& cuts_to_zeros() const { return cuts_to_zeros_; }
    // What the user should know of how the file was read, though no sound was lost ("its header
    // states 9.7 s of sound, the file holds 19.5 s ...; read to the end of the file"), without the
    // file's name: the aligner gives each to the Timeline's warnings, naming the file.
    const std::vector<std::string>& notes() const { return notes_; }
    void add_note(std::string note);

protected:
    // Notes `frames` frames of silence read in place of damaged data from frame `at_frame` on,
    // joined to the stretch before when they follow it; those before the frame an earlier reading
    // was taken over until (take_first_reading) are its, and noted already.
    void note_lost_audio(std::size_t at_frame, std::size_t frames);
    // Whether this reading itself has read silence in place of damaged data.
    bool has_lost_audio_read() const { return has_lost_audio_read_; }
    // The same for `frames` frames of silence read in place of a codec's pause frames.
    void note_codec_pause(std::size_t at_frame, std::size_t frames);
    // The same for `frames` frames from `at_frame` cut off mid-wave to exact zeros.
    void note_cut_to_zeros(std::size_t at_frame, std::size_t frames);

private:
    std::vector<LostAudio> lost_audio_;
    std::vector<CodecPause> codec_pauses_;
    std::vector<CutToZeros> cuts_to_zeros_;
    std::vector<std::string> notes_;
    std::size_t frames_read_ = 0;
    std::size_t non_finite_frames_ = 0;
    std::size_t first_non_finite_frame_ = 0;
    // Frames before this one were read by an earlier reading (take_first_reading).
    std::size_t taken_until_frame_ = 0;
    bool has_lost_audio_read_ = false;
    bool is_end_noted_ = false;
    // read()'s frames as the source holds them, before non-numbers are made 0.
    virtual std::size_t read_frames(float* mono, std::size_t max_frames) = 0;
    // skip_to()'s move, where the reader has one.
    virtual bool seek_frames(std::size_t /*frame*/) { return false; }
};

// The largest sample read() takes. A float recording holds -1..1, or an integer format's values
// written as floats (a careless converter's), which reach 2^31 at most; past that no level means
// anything, and the squares of samples near 1e34 overflowed a float: such a WAV was called "no
// speech found", as if it held silence.
constexpr float kMostSampleMagnitude = 4294967296.0f;

// The sample rates and channel counts every reader accepts. A rate outside them is a damaged
// header (a WAV stating 10^9 Hz reached libsamplerate, whose ratio stops at 256, as an internal
// error): below 4 kHz no speech is left to align, and 384 kHz is the highest any recorder writes.
constexpr int kMinSampleRateHz = 4000;
constexpr int kMaxSampleRateHz = 384000;
constexpr int kMaxChannels = 64;

// Whether `sample_rate_hz` and `channels` are ones every reader takes.
inline bool is_readable_format(int sample_rate_hz, int channels) {
    return sample_rate_hz >= kMinSampleRateHz && sample_rate_hz <= kMaxSampleRateHz && channels >= 1 &&
           channels <= kMaxChannels;
}

// "unsupported header: 1 channels at 1000000000 Hz (talkface reads 1-64 channels at 4000-384000 Hz)".
inline std::string unsupported_format_text(const std::string& what, int sample_rate_hz, int channels) {
    return "unsupported " + what + ": " + std::to_string(channels) + " channels at " +
           std::to_string(sample_rate_hz) + " Hz (talkface reads 1-" + std::to_string(kMaxChannels) +
           " channels at " + std::to_string(kMinSampleRateHz) + "-" + std::to_string(kMaxSampleRateHz) +
           " Hz)";
}

// \throws talkface::FileError if the file is missing or cannot be opened, talkface::ParseError
//         naming the reason if neither libsndfile nor FFmpeg reads it as audio (or a video has no
//         sound track), talkface::InvalidArgument if it has no frames.
std::unique_ptr<AudioSource> open_audio_file(const std::string& path);

// The name of a WAV file's codec (libsndfile's: "GSM 6.10", "IMA ADPCM", "64 bit float") when it
// is one browsers do not play, else empty (also for a file libsndfile cannot open: reading it
// says why). Chromium 156 plays a WAV of 8- to 32-bit PCM, 32-bit float, A-law or mu-law, of any
// channel count, RF64 too; it refuses GSM 06.10, IMA and Microsoft ADPCM and 64-bit float (each
// tried as a data: URI in an <audio> element, bench/README.md "Session 13"). Firefox and Safari
// play less: what Chromium refuses, none plays.
std::string wav_codec_browsers_do_not_play(const std::string& path);

// \throws talkface::InvalidArgument naming the field of `audio` that is malformed.
std::unique_ptr<AudioSource> open_audio_view(const AudioView& audio);

}  // namespace talkface::detail

#endif
