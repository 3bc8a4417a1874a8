"""talkface: talking cartoon faces.

Load or build a face, pose it, give it an expression and a mouth shape, and draw it as SVG::

    import talkface
    face = talkface.FaceModel.default()            # or talkface.FaceModel.load("face.xml")
    state = talkface.FaceState(pose=talkface.Pose(beta_deg=10.0),
                               mouth=talkface.mouth_controls(face, talkface.MouthShape.a))
    talkface.SvgAnimator(face).write_svg("face.svg", state)

Coordinates are image pixels with y down; angles are degrees; FAPUs are pixels. Errors are
talkface.Error subclasses whose messages name the file, line, point or parameter that was wrong:
ParseError, FileError (also an OSError), InvalidArgument (also a ValueError), AlignmentError,
Cancelled.

Many speeches at once, on one machine or a Dask cluster: talkface.batch (docs/batch.md).

talkface is licensed under the Apache License, Version 2.0 (the LICENSE file; __license__).
"""

from ._talkface import (
    AlphaMode,
    audio_duration_s,
    export_format_for_path,
    export_format_names,
    export_to_file,
    export_to_string,
    read_timing_file,
    read_timing_string,
    time_transcript,
    timing_format_names,
    write_timing_string,
    AnimationEncoding,
    AlignOptions,
    AlignmentError,
    Animation,
    Cancelled,
    CheckMode,
    Error,
    ErrorCode,
    Expression,
    ExpressionEvent,
    ExpressionEventKind,
    ExpressionSimulator,
    ExpressionStyle,
    FaceVideoOptions,
    FaceColors,
    FaceModel,
    FaceState,
    FileError,
    FaceLook,
    FrameLayout,
    FrameOptions,
    FrameRenderer,
    InvalidArgument,
    LiftedFace,
    LipSyncOptions,
    MouthControls,
    MouthInterpolation,
    MISMATCH_LOUDNESS_STEP_S,
    MouthKeyFrame,
    MouthShape,
    NoseBridgeSide,
    ParseError,
    Pose,
    ProjectedFace,
    Rotation3D,
    Sentence,
    SentenceCutMode,
    ShapeOnsetTable,
    SpeechAligner,
    SvgAnimationOptions,
    SvgAnimator,
    TextMismatch,
    SvgOptions,
    Syllable,
    TIMELINE_JSON_VERSION,
    Timeline,
    UserEventMode,
    VideoFormat,
    VideoOptions,
    VideoWriter,
    WebLink,
    WebPageApp,
    WebPageAudio,
    WebPageOptions,
    WrittenForm,
    __version__,
    additional_point_ids,
    alignment_plot_svg,
    all_mouth_shapes,
    animate,
    apply_expression,
    apply_mouth,
    build_web_page,
    check_video_options,
    depth_in_d,
    expression_event_kind_from_name,
    expression_event_kind_name,
    is_valid_pinyin,
    kLowAlignmentConfidence,
    kGenericSpeechPinyin,
    kMaxPoseAngleDeg,
    kMaxSvgDecimals,
    key_frames_json,
    key_frames_tsv,
    lift_face,
    load_timeline_json,
    load_transcript,
    mandarin_syllables,
    mouth_controls,
    mouth_frames,
    mouth_key_frames,
    mouth_shape_from_name,
    mouth_shape_name,
    neutral_mouth_controls,
    place_face,
    project_face,
    read_transcript,
    render_video,
    rotation_origin,
    save_timeline_json,
    syllable_mouth_shapes,
    timeline_end_s,
    timeline_from_json,
    timeline_to_json,
    validate_expression_events,
    video_format_from_path,
    version,
    write_alignment_plot_svg,
    write_web_page,
)


# Face from a photo is the _talkface_photo module (it loads OpenCV, libpng, libjpeg and dlib through
# libtalkface_photo), imported on the first use of one of these names, so that `import talkface`
# costs a program that never reads a photo nothing of it.
_PHOTO_NAMES = ("PhotoFaceResult", "PhotoFeature", "face_from_photo", "has_dlib_locator")


def _photo_module():
    try:
        from . import _talkface_photo
    except ImportError as error:
        raise ImportError(
            "talkface's face from a photo is not available: this talkface was built without the photo "
            "stage (TALKFACE_WITH_PHOTO=OFF) or its library cannot be loaded: " + str(error)
        ) from error
    return _talkface_photo


def __getattr__(name):
    if name in _PHOTO_NAMES:
        return getattr(_photo_module(), name)
    raise AttributeError("module 'talkface' has no attribute " + repr(name))


def _face_model_from_photo(photo, **options):
    return _photo_module().face_model_from_photo(photo, **options)


_face_model_from_photo.__doc__ = """The face model (photo pixels) of a frontal photo of a neutral face.

Loads the photo stage on first use; talkface.face_from_photo() also gives each feature's confidence.
Takes the keyword arguments of face_from_photo (locator, face_index, cascade_dir, dlib_model_path).

Example:
    >>> face = talkface.FaceModel.from_photo("me.jpg")
    >>> face.save("me.xml")
"""
FaceModel.from_photo = staticmethod(_face_model_from_photo)


__license__ = "Apache-2.0"


def default_face() -> FaceModel:
    """The built-in default face (same as FaceModel.default()).

    Example:
        >>> face = talkface.default_face()
        >>> face.fapu("d")
    """
    return FaceModel.default()


__all__ = [
    "AlphaMode",
    "audio_duration_s",
    "export_format_for_path",
    "export_format_names",
    "export_to_file",
    "export_to_string",
    "read_timing_file",
    "read_timing_string",
    "time_transcript",
    "timing_format_names",
    "write_timing_string",
    "AnimationEncoding",
    "AlignOptions",
    "AlignmentError",
    "Animation",
    "Cancelled",
    "CheckMode",
    "Error",
    "ErrorCode",
    "Expression",
    "ExpressionEvent",
    "ExpressionEventKind",
    "ExpressionSimulator",
    "ExpressionStyle",
    "FaceVideoOptions",
    "FaceColors",
    "FaceModel",
    "FaceState",
    "FileError",
    "FaceLook",
    "FrameLayout",
    "FrameOptions",
    "FrameRenderer",
    "InvalidArgument",
    "LiftedFace",
    "LipSyncOptions",
    "MouthControls",
    "MouthInterpolation",
    "MouthKeyFrame",
    "MISMATCH_LOUDNESS_STEP_S",
    "MouthShape",
    "NoseBridgeSide",
    "ParseError",
    "Pose",
    "ProjectedFace",
    "Rotation3D",
    "Sentence",
    "SentenceCutMode",
    "ShapeOnsetTable",
    "SpeechAligner",
    "SvgAnimationOptions",
    "SvgAnimator",
    "TextMismatch",
    "SvgOptions",
    "Syllable",
    "TIMELINE_JSON_VERSION",
    "Timeline",
    "UserEventMode",
    "VideoFormat",
    "VideoOptions",
    "VideoWriter",
    "WebLink",
    "WebPageApp",
    "WebPageAudio",
    "WebPageOptions",
    "WrittenForm",
    "__version__",
    "additional_point_ids",
    "alignment_plot_svg",
    "all_mouth_shapes",
    "animate",
    "apply_expression",
    "apply_mouth",
    "build_web_page",
    "check_video_options",
    "default_face",
    "depth_in_d",
    "expression_event_kind_from_name",
    "expression_event_kind_name",
    "is_valid_pinyin",
    "kLowAlignmentConfidence",
    "kGenericSpeechPinyin",
    "kMaxPoseAngleDeg",
    "kMaxSvgDecimals",
    "key_frames_json",
    "key_frames_tsv",
    "lift_face",
    "load_timeline_json",
    "load_transcript",
    "mandarin_syllables",
    "mouth_controls",
    "mouth_frames",
    "mouth_key_frames",
    "mouth_shape_from_name",
    "mouth_shape_name",
    "neutral_mouth_controls",
    "place_face",
    "project_face",
    "read_transcript",
    "render_video",
    "rotation_origin",
    "save_timeline_json",
    "syllable_mouth_shapes",
    "timeline_end_s",
    "timeline_from_json",
    "timeline_to_json",
    "validate_expression_events",
    "video_format_from_path",
    "version",
    "write_alignment_plot_svg",
    "write_web_page",
]
