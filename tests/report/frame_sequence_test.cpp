// FrameSequenceWriter: an MP4 (H.264) and a WebM (VP9) read back by
// OpenCV's own decoder have every frame, at the written size, with the
// written brightness; a GIF read back by giflib has every frame, its delays
// and its colours; the extension decides the form, and others are refused.
#include "stochtex/report/frame_sequence.h"

#include <gif_lib.h>
extern "C" {
#include <libavutil/log.h>
}
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/video_encoder.h"
#include "test_util.h"

using namespace stochtex;
namespace fs = std::filesystem;

namespace {

class FrameSequence : public test::ScratchFolder {};

// Frame k is uniformly k / (frames − 1) gray, so each frame read back says
// which one it is.
Image uniform(int w, int h, int channels, float v) { return Image(w, h, channels, v); }

}  // namespace

// The four-character code of a video's codec, as OpenCV reads it.
std::string fourcc(cv::VideoCapture& in) {
    const int code = int(in.get(cv::CAP_PROP_FOURCC));
    std::string s;
    for (int k = 0; k < 4; ++k) s += char((code >> (8 * k)) & 0xff);
    return s;
}

TEST(SequenceFormat, TheExtensionDecidesAndOthersAreRefused) {
    EXPECT_EQ(sequenceFormat("out/frames"), SequenceFormat::Folder);
    EXPECT_EQ(sequenceFormat("out/frames.v2/"), SequenceFormat::Folder);
    EXPECT_EQ(sequenceFormat("clip.MP4"), SequenceFormat::Mp4);
    EXPECT_EQ(sequenceFormat("clip.webm"), SequenceFormat::WebM);
    EXPECT_EQ(sequenceFormat("clip.WebP"), SequenceFormat::AnimatedWebp);
    EXPECT_EQ(sequenceFormat("clip.gif"), SequenceFormat::Gif);
    EXPECT_TRUE(isVideoPath("clip.gif"));
    EXPECT_FALSE(isVideoPath("frames"));
    try {
        sequenceFormat("run.anything");
        FAIL() << "an unknown extension was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("run.anything: cannot write frames as \".anything\""), std::string::npos)
            << e.what();
    }
}

TEST_F(FrameSequence, AnUnknownExtensionWritesNothing) {
    EXPECT_THROW(FrameSequenceWriter((dir_ / "run.avi").string(), 16, 16, 30.0, ""), InputError);
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(FrameSequence, AnMp4PathWritesOneVideoWithEveryFrame) {
    const std::string path = (dir_ / "clip.mp4").string();
    const int frames = 7, w = 48, h = 32;
    {
        FrameSequenceWriter out(path, w, h, 25.0, "", Transfer::Linear);  // the codec alone
        for (int k = 0; k < frames; ++k) out.write(uniform(w, h, k % 2 ? 3 : 1, float(k) / float(frames - 1)));
        EXPECT_EQ(out.finish(), path);
        EXPECT_EQ(out.previewPath(), (dir_ / "clip.webp").string());
    }
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++files;
    EXPECT_EQ(files, 2) << "only the video and its animated preview, no frames or temporary file";
    EXPECT_GT(fs::file_size(dir_ / "clip.webp"), 0u);

    cv::VideoCapture in(path, cv::CAP_FFMPEG);
    ASSERT_TRUE(in.isOpened());
    // H.264, what browsers play (MPEG-4 Part 2 reads "mp4v" or "FMP4").
    EXPECT_TRUE(fourcc(in) == "avc1" || fourcc(in) == "h264") << fourcc(in);
    int read = 0;
    cv::Mat frame;
    while (in.read(frame)) {
        ASSERT_EQ(frame.cols, w);
        ASSERT_EQ(frame.rows, h);
        // FFmpeg's BGR → YUV 4:2:0 → BGR round trip (video range) and the
        // codec's quantisation move a flat frame by a few levels: 8 levels,
        // still far below the 42.5 levels between frames, so each frame is
        // identified.
        const double expected = 255.0 * read / (frames - 1);
        EXPECT_NEAR(cv::mean(frame)[0], expected, 8.0) << "frame " << read;
        ++read;
    }
    EXPECT_EQ(read, frames);
}

TEST_F(FrameSequence, AWebmPathWritesOneVp9Video) {
    const std::string path = (dir_ / "clip.webm").string();
    const int frames = 5;
    {
        FrameSequenceWriter out(path, 32, 16, 10.0, "", Transfer::Linear);
        for (int k = 0; k < frames; ++k) out.write(uniform(32, 16, 3, float(k) / float(frames - 1)));
        EXPECT_EQ(out.finish(), path);
        EXPECT_EQ(out.previewPath(), (dir_ / "clip.webp").string());
    }
    cv::VideoCapture in(path, cv::CAP_FFMPEG);
    ASSERT_TRUE(in.isOpened());
    // OpenCV reads no four-character code from a WebM: the Matroska header names the codec.
    std::ifstream file(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_NE(bytes.find("V_VP9"), std::string::npos) << "not VP9";
    int read = 0;
    cv::Mat frame;
    while (in.read(frame)) {
        EXPECT_NEAR(cv::mean(frame)[0], 255.0 * read / (frames - 1), 8.0) << "frame " << read;
        ++read;
    }
    EXPECT_EQ(read, frames);
}

// 30 fps in centiseconds: frame k starts at round(100·k/30), so the delays
// are 3, 4, 3, 3, 4, 3 and the clip lasts its 20 cs; frame k is gray k/5
// in its palette, exactly (a flat frame needs one colour).
TEST_F(FrameSequence, AGifPathWritesEveryFrameWithItsDelay) {
    const std::string path = (dir_ / "clip.gif").string();
    {
        FrameSequenceWriter out(path, 20, 10, 30.0, "", Transfer::Linear);
        for (int k = 0; k < 6; ++k) out.write(uniform(20, 10, k % 2 ? 3 : 1, float(k) / 5.0f));
        EXPECT_EQ(out.finish(), path);
        EXPECT_TRUE(out.previewPath().empty());
    }
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++files;
    EXPECT_EQ(files, 1) << "the GIF alone, no frames or temporary file";
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
    ASSERT_NE(gif, nullptr) << GifErrorString(error);
    ASSERT_EQ(DGifSlurp(gif), GIF_OK);
    EXPECT_EQ(gif->SWidth, 20);
    EXPECT_EQ(gif->SHeight, 10);
    ASSERT_EQ(gif->ImageCount, 6);
    const int delays[] = {3, 4, 3, 3, 4, 3};
    for (int k = 0; k < 6; ++k) {
        GraphicsControlBlock control;
        ASSERT_EQ(DGifSavedExtensionToGCB(gif, k, &control), GIF_OK);
        EXPECT_EQ(control.DelayTime, delays[k]) << "frame " << k;
        const SavedImage& image = gif->SavedImages[k];
        const GifColorType c = image.ImageDesc.ColorMap->Colors[image.RasterBits[55]];
        EXPECT_EQ(c.Red, std::lround(255.0 * k / 5)) << "frame " << k;
        EXPECT_EQ(c.Green, c.Red);
        EXPECT_EQ(c.Blue, c.Red);
    }
    DGifCloseFile(gif, &error);
}

// Above 50 fps a GIF keeps its pace with fewer frames: a delay under 2 cs
// would be stretched to 10 cs by browsers. 60 fps: frame k starts at
// round(100·k/60) = 0, 2, 3, 5, 7, 8, …; those under 2 cs after the last kept
// one go, leaving 8 of 12 frames, 2 or 3 cs each, 20 cs in all.
TEST_F(FrameSequence, AFastGifDropsFramesRatherThanSlowingDown) {
    const std::string path = (dir_ / "fast.gif").string();
    {
        FrameSequenceWriter out(path, 8, 8, 60.0, "");
        for (int k = 0; k < 12; ++k) out.write(uniform(8, 8, 1, 0.5f));
        out.finish();
    }
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
    ASSERT_NE(gif, nullptr);
    ASSERT_EQ(DGifSlurp(gif), GIF_OK);
    EXPECT_EQ(gif->ImageCount, 8);
    int total = 0;
    for (int k = 0; k < gif->ImageCount; ++k) {
        GraphicsControlBlock control;
        ASSERT_EQ(DGifSavedExtensionToGCB(gif, k, &control), GIF_OK);
        EXPECT_GE(control.DelayTime, 2);
        total += control.DelayTime;
    }
    EXPECT_EQ(total, 20) << "12 frames at 60 fps last 20 cs";
    DGifCloseFile(gif, &error);
}

TEST_F(FrameSequence, AFolderGetsPngFramesAndTheNamedVideo) {
    {
        FrameSequenceWriter out(dir_.string(), 16, 16, 30.0, "seq.mp4");
        for (int k = 0; k < 3; ++k) out.write(uniform(16, 16, 1, 0.5f));
        EXPECT_EQ(out.finish(), (dir_ / "seq.mp4").string());
    }
    for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png", "seq.mp4"})
        EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << name;
}

TEST_F(FrameSequence, AnUnfinishedVideoLeavesNoFile) {
    {
        FrameSequenceWriter out((dir_ / "clip.mp4").string(), 16, 16, 30.0, "");
        out.write(uniform(16, 16, 1, 0.5f));
    }
    EXPECT_TRUE(fs::is_empty(dir_));
}

// Sequences side by side, by index (two may share a name): videos opened at
// once, PNG frames <name>-NNN.png encoded with the set's transfer.
TEST_F(FrameSequence, ASetWritesEachSequencesVideoAndFrames) {
    {
        FrameSequenceSet out(dir_.string(), {"none", "smooth"}, 16, 8, {.video = true, .frames = true});
        EXPECT_TRUE(out.writes());
        for (int k = 0; k < 3; ++k)
            for (size_t m = 0; m < 2; ++m) out.write(m, k, uniform(16, 8, 1, 0.25f * float(m + 1)));
        EXPECT_EQ(out.finish(),
                  (std::vector<std::string>{(dir_ / "none.mp4").string(), (dir_ / "smooth.mp4").string()}));
    }
    for (const char* name : {"none-000.png", "none-002.png", "smooth-001.png", "none.mp4", "smooth.mp4", "smooth.webp"})
        EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << name;
    EXPECT_FALSE(fs::exists(dir_ / "none-003.png"));
    // sRGB (the default transfer) of linear 0.5 is code 188 (0.7354 · 255 = 187.5, rounded half up).
    const Image png = readImage((dir_ / "smooth-001.png").string());
    EXPECT_NEAR(png.at(3, 3) * 255.0f, 188.0f, 0.5f);

    // The videos are opened at once: a folder that is not there fails before any frame.
    EXPECT_ANY_THROW(FrameSequenceSet((dir_ / "missing").string(), {"a"}, 16, 8, {.video = true}));
    FrameSequenceSet nothing(dir_.string(), {"other"}, 16, 8, {});
    EXPECT_FALSE(nothing.writes());
    nothing.write(0, 0, uniform(16, 8, 1, 0.5f));
    EXPECT_TRUE(nothing.finish().empty());
    EXPECT_FALSE(fs::exists(dir_ / "other-000.png"));
    EXPECT_FALSE(fs::exists(dir_ / "other.mp4"));
}

namespace stochtex {
namespace {

TEST(WallClockFrames, RepeatsSlowFramesSkipsFastOnesAndCutsStalls) {
    // Pictures A (t = 0), B (0.05), C (0.10), D (0.35), E (60.35), ... at 10 fps;
    // frame k shows the picture on screen at k / 10.
    WallClockFrames clock(10, 2.0);
    EXPECT_EQ(clock.framesBefore(0.0), 0);   // A is held
    EXPECT_EQ(clock.framesBefore(0.05), 1);  // frame 0 (t = 0) is A
    EXPECT_EQ(clock.framesBefore(0.10), 0);  // B was on screen at no frame's time: skipped
    EXPECT_EQ(clock.framesBefore(0.35), 3);  // frames 1, 2, 3 (t = 0.1, 0.2, 0.3) are C
    EXPECT_EQ(clock.written(), 4);
    // D stays on screen for 60 s: 2 s of it are written, and the frames after keep their spacing.
    EXPECT_EQ(clock.framesBefore(60.35), 20);
    EXPECT_EQ(clock.framesBefore(60.40), 0);
    EXPECT_EQ(clock.framesBefore(60.45), 1);
    EXPECT_EQ(clock.written(), 25);
    // Whatever the pace, the frames written before a picture at t are those with k / fps < t.
    WallClockFrames steady(30);
    long long total = 0;
    for (int k = 0; k <= 1000; ++k) total += steady.framesBefore(k * 0.01373);
    EXPECT_EQ(total, (long long)std::ceil(1000 * 0.01373 * 30));
    EXPECT_THROW(WallClockFrames(0), InputError);
    EXPECT_THROW(WallClockFrames(30, std::nan("")), InputError);
    EXPECT_THROW(WallClockFrames(30, 1e30), InputError);
}

}  // namespace
}  // namespace stochtex

// Issue "Hostile input on the new surfaces", item 6: FFmpeg's own log lines
// (a missing encoder printed three before our message) stay out of the
// terminal; the message of a failure carries FFmpeg's last error instead.
TEST(VideoEncoder, FfmpegsLogStaysOutOfTheTerminal) {
    (void)hasVideoEncoder(VideoCodec::H264);  // what every video writer asks first
    testing::internal::CaptureStderr();
    av_log(nullptr, AV_LOG_ERROR, "a planted FFmpeg error\n");
    av_log(nullptr, AV_LOG_WARNING, "a planted FFmpeg warning\n");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
