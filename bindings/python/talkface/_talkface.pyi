# Type stubs for the compiled talkface._talkface module (kept by hand next to bindings/python/src/).
import enum
import os
from typing import Callable, ClassVar, Sequence

import numpy
import numpy.typing

_Point2 = tuple[float, float]
_Point3 = tuple[float, float, float]
_PathLike = str | os.PathLike[str]
_FloatArray = numpy.typing.NDArray[numpy.float64]

__version__: str
kMaxPoseAngleDeg: float
# A syllable whose confidence is below this (0.5) may be more than 100 ms off: check it (flags at most
# 10% of right syllables in every condition of the benchmark's human speech, 5.2% pooled, and catches
# 79% of those >100 ms off; SpeechAligner).
kLowAlignmentConfidence: float
kGenericSpeechPinyin: str
# The most digits after the point SvgOptions.decimals may ask for (6).
kMaxSvgDecimals: int

def version() -> str: ...

class ErrorCode(enum.Enum):
    invalid_argument = 1
    file = 2
    parse = 3
    alignment = 4
    cancelled = 5
    out_of_memory = 6
    internal = 7

class Error(RuntimeError):
    code: ErrorCode

class ParseError(Error):
    path: str
    line: int
    column: int
    item: str

class FileError(Error, OSError):
    filename: str

class InvalidArgument(Error, ValueError):
    parameter: str

class AlignmentError(Error): ...
class Cancelled(Error): ...

class FaceColors:
    skin: str
    hair: str
    brows: str
    eye_white: str
    iris: str
    lips: str
    mouth_inside: str
    outline: str
    def __init__(self) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class FaceModel:
    kPointCount: ClassVar[int]
    kFapuCount: ClassVar[int]
    kFileFormatVersion: ClassVar[int]
    colors: FaceColors
    name: str
    def __init__(self) -> None: ...
    @staticmethod
    def default() -> FaceModel: ...
    @staticmethod
    def default_face() -> FaceModel: ...
    @staticmethod
    def load(path: _PathLike) -> FaceModel: ...
    @staticmethod
    def from_xml(xml: str, source_name: str = "<string>") -> FaceModel: ...
    @staticmethod
    def from_photo(photo: _PathLike | numpy.typing.NDArray[numpy.uint8], *, locator: str = "automatic",
                   face_index: int = -1, cascade_dir: str = "", dlib_model_path: str = "") -> FaceModel: ...
    def save(self, path: _PathLike) -> None: ...
    def to_xml(self) -> str: ...
    @staticmethod
    def point_ids() -> list[str]: ...
    @staticmethod
    def fapu_names() -> list[str]: ...
    @staticmethod
    def is_point_id(id: str) -> bool: ...
    def point(self, id: str) -> _Point2: ...
    def set_point(self, id: str, image_xy: _Point2) -> None: ...
    def points(self) -> _FloatArray: ...
    def set_points(self, points: numpy.typing.ArrayLike) -> None: ...
    def fapu(self, name: str) -> float: ...
    def set_fapu(self, name: str, value_px: float) -> None: ...
    def fapus(self) -> dict[str, float]: ...
    def __eq__(self, other: object) -> bool: ...
    def __copy__(self) -> FaceModel: ...
    def __deepcopy__(self, memo: dict) -> FaceModel: ...

class LiftedFace:
    @property
    def origin(self) -> _Point2: ...
    @property
    def d(self) -> float: ...
    @property
    def ids(self) -> list[str]: ...
    @property
    def local_xyz(self) -> _FloatArray: ...
    def local(self, id: str) -> _Point3: ...

def lift_face(face: FaceModel) -> LiftedFace: ...
def additional_point_ids() -> list[str]: ...
def depth_in_d(id: str) -> float: ...
def rotation_origin(face: FaceModel) -> _Point2: ...
def place_face(face: FaceModel, origin: _Point2, d_px: float) -> FaceModel: ...

class Rotation3D:
    def __init__(self, alpha_deg: float = 0.0, beta_deg: float = 0.0, gamma_deg: float = 0.0) -> None: ...
    @property
    def alpha_deg(self) -> float: ...
    @property
    def beta_deg(self) -> float: ...
    @property
    def gamma_deg(self) -> float: ...
    def matrix(self) -> _FloatArray: ...
    def rotate(self, local_xyz: numpy.typing.ArrayLike) -> _FloatArray: ...
    def unrotate(self, local_xyz: numpy.typing.ArrayLike) -> _FloatArray: ...
    def __eq__(self, other: object) -> bool: ...

class Expression:
    blink_left: float
    blink_right: float
    smile: float
    brows: float
    def __init__(
        self, blink_left: float = 0.0, blink_right: float = 0.0, smile: float = 0.0, brows: float = 0.0
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...

def apply_expression(face: FaceModel, expression: Expression) -> FaceModel: ...

class MouthShape(enum.Enum):
    m = 0
    f = 1
    h_prime = 2
    h = 3
    r = 4
    z = 5
    a = 6
    i = 7
    u = 8
    e = 9
    o = 10
    n = 11

def all_mouth_shapes() -> list[MouthShape]: ...
def mouth_shape_name(shape: MouthShape) -> str: ...
def mouth_shape_from_name(name: str) -> MouthShape: ...

class MouthControls:
    up: _Point2
    down: _Point2
    left: _Point2
    right: _Point2
    def __init__(
        self,
        up: _Point2 = (0.0, 0.0),
        down: _Point2 = (0.0, 0.0),
        left: _Point2 = (0.0, 0.0),
        right: _Point2 = (0.0, 0.0),
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...

def neutral_mouth_controls(neutral: FaceModel) -> MouthControls: ...
def mouth_controls(neutral: FaceModel, shape: MouthShape) -> MouthControls: ...
def apply_mouth(neutral: FaceModel, controls: MouthControls) -> FaceModel: ...

class Pose:
    alpha_deg: float
    beta_deg: float
    gamma_deg: float
    def __init__(self, alpha_deg: float = 0.0, beta_deg: float = 0.0, gamma_deg: float = 0.0) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class FaceState:
    pose: Pose
    expression: Expression
    mouth: MouthControls | None
    def __init__(
        self, pose: Pose = ..., expression: Expression = ..., mouth: MouthControls | None = None
    ) -> None: ...

class NoseBridgeSide(enum.Enum):
    left = 0
    right = 1

class ProjectedFace:
    @property
    def ids(self) -> list[str]: ...
    @property
    def image_xy(self) -> _FloatArray: ...
    @property
    def left_contour(self) -> list[str]: ...
    @property
    def right_contour(self) -> list[str]: ...
    @property
    def nose_bridge(self) -> NoseBridgeSide: ...
    @property
    def origin(self) -> _Point2: ...
    @property
    def d(self) -> float: ...
    @property
    def face(self) -> FaceModel: ...
    def point(self, id: str) -> _Point2: ...
    def hair_polygon(self) -> _FloatArray: ...

def project_face(neutral: FaceModel, state: FaceState) -> ProjectedFace: ...

class SvgOptions:
    background: str | None
    draw_clothes: bool
    clothes: str
    stroke_width_in_d: float
    decimals: int
    width_px: int
    height_px: int
    def __init__(
        self,
        background: str | None = "#dde8f0",
        draw_clothes: bool = True,
        clothes: str = "#2f4f7f",
        stroke_width_in_d: float = 0.025,
        decimals: int = 2,
        width_px: int = 0,
        height_px: int = 0,
    ) -> None: ...

class SvgAnimator:
    def __init__(self, face: FaceModel, options: SvgOptions = ...) -> None: ...
    @property
    def face(self) -> FaceModel: ...
    @property
    def options(self) -> SvgOptions: ...
    def render_svg(self, state: FaceState) -> str: ...
    def write_svg(self, path: _PathLike, state: FaceState) -> None: ...
    def render_animation_svg(self, animation: Animation, options: SvgAnimationOptions = ...) -> str: ...
    def write_animation_svg(self, path: _PathLike, animation: Animation,
                            options: SvgAnimationOptions = ...) -> None: ...
    def render_animation_lottie(self, animation: Animation, tolerance_px: float = 0.3) -> str: ...
    def write_animation_lottie(self, path: _PathLike, animation: Animation,
                               tolerance_px: float = 0.3) -> None: ...

class FrameLayout(enum.Enum):
    announcer = 0
    face = 1

class AlphaMode(enum.Enum):
    straight = 0
    premultiplied = 1

class FrameOptions:
    width_px: int
    height_px: int
    layout: FrameLayout
    background: str | None
    draw_clothes: bool
    clothes: str
    stroke_width_in_d: float
    face_origin_px: tuple[float, float] | None
    face_d_px: float
    alpha: AlphaMode
    def __init__(
        self,
        width_px: int = 1280,
        height_px: int = 720,
        layout: FrameLayout = ...,
        background: str | None = "#1d3b5c",
        draw_clothes: bool = True,
        clothes: str = "#2f4f7f",
        stroke_width_in_d: float = 0.025,
        face_origin_px: tuple[float, float] | None = None,
        face_d_px: float = 0.0,
        alpha: AlphaMode = ...,
    ) -> None: ...

class FrameRenderer:
    def __init__(self, face: FaceModel, options: FrameOptions = ...) -> None: ...
    @property
    def face(self) -> FaceModel: ...
    @property
    def options(self) -> FrameOptions: ...
    @property
    def width_px(self) -> int: ...
    @property
    def height_px(self) -> int: ...
    def render_frame_rgba(self, state: FaceState) -> numpy.typing.NDArray[numpy.uint8]: ...
    def set_background_image(self, image: numpy.typing.NDArray[numpy.uint8]) -> None: ...

class AnimationEncoding(enum.Enum):
    keyframes = 0
    frames = 1

class SvgAnimationOptions:
    encoding: AnimationEncoding
    tolerance_px: float
    def __init__(self, encoding: AnimationEncoding = ..., tolerance_px: float = ...) -> None: ...

class WebPageApp(enum.Enum):
    plain = 0
    announcer = 1
    audiobook = 2

class WebPageAudio(enum.Enum):
    compressed = 0
    original = 1
    link = 2

class WebLink:
    text: str
    url: str
    def __init__(self, text: str, url: str) -> None: ...

class WebPageOptions:
    app: WebPageApp
    title: str
    links: list[WebLink]
    animation: SvgAnimationOptions
    audio: WebPageAudio
    audio_bitrate_bps: int
    audio_url: str
    stage_width_px: int
    stage_height_px: int
    stage_colour: str
    background_image_path: str
    face_origin_px: tuple[float, float] | None
    face_d_px: float
    def __init__(self, app: WebPageApp = ..., title: str = "", links: list[WebLink] = ...,
                 animation: SvgAnimationOptions = ..., audio: WebPageAudio = ...,
                 audio_bitrate_bps: int = 0, audio_url: str = "",
                 stage_width_px: int = 800, stage_height_px: int = 450, stage_colour: str = "#1d3b5c",
                 background_image_path: str = "", face_origin_px: tuple[float, float] | None = None,
                 face_d_px: float = 0.0) -> None: ...

def build_web_page(animator: SvgAnimator, animation: Animation, timeline: Timeline, audio_path: _PathLike,
                   options: WebPageOptions = ...) -> str: ...
def write_web_page(path: _PathLike, animator: SvgAnimator, animation: Animation, timeline: Timeline,
                   audio_path: _PathLike, options: WebPageOptions = ...) -> None: ...

class Sentence:
    text: str
    start_s: float
    end_s: float
    starts_paragraph: bool
    def __init__(self, text: str = "", start_s: float = 0.0, end_s: float = 0.0,
                 starts_paragraph: bool = False) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class Syllable:
    text: str
    pinyin: str
    sentence: int
    start_s: float
    end_s: float
    final_start_s: float | None
    confidence: float
    pause_after: bool
    generic_speech: bool
    def __init__(
        self,
        text: str = "",
        pinyin: str = "",
        sentence: int = 0,
        start_s: float = 0.0,
        end_s: float = 0.0,
        final_start_s: float | None = None,
        confidence: float = 1.0,
        pause_after: bool = False,
        generic_speech: bool = False,
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...

MISMATCH_LOUDNESS_STEP_S: float

class TextMismatch:
    start_s: float
    end_s: float
    first_syllable: int
    syllable_count: int
    expected_text: str
    loudness: list[float]
    def __init__(
        self,
        start_s: float = ...,
        end_s: float = ...,
        first_syllable: int = ...,
        syllable_count: int = ...,
        expected_text: str = ...,
        loudness: list[float] = ...,
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class WrittenForm:
    text: str
    first_syllable: int
    syllable_count: int
    def __init__(self, text: str = "", first_syllable: int = 0, syllable_count: int = 0) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class Timeline:
    sentences: list[Sentence]
    syllables: list[Syllable]
    warnings: list[str]
    duration_s: float
    written_forms: list[WrittenForm]
    mismatches: list[TextMismatch]
    def __init__(
        self,
        sentences: list[Sentence] = ...,
        syllables: list[Syllable] = ...,
        warnings: list[str] = ...,
        duration_s: float = 0.0,
        written_forms: list[WrittenForm] = ...,
        mismatches: list[TextMismatch] = ...,
    ) -> None: ...

def read_transcript(text: str, source_name: str = "<transcript>", read_pinyin: bool = True,
                    keep_directions: bool = False) -> Timeline: ...
def load_transcript(path: _PathLike, read_pinyin: bool = True, encoding: str = "",
                    keep_directions: bool = False) -> Timeline: ...

TIMELINE_JSON_VERSION: int
def timeline_to_json(timeline: Timeline, with_times: bool = True) -> str: ...
def timeline_from_json(text: str, source_name: str = "<timeline>") -> Timeline: ...
def load_timeline_json(path: _PathLike) -> Timeline: ...
def save_timeline_json(path: _PathLike, timeline: Timeline, with_times: bool = True) -> None: ...
def export_format_names() -> list[str]: ...
def export_format_for_path(path: str) -> str: ...
def export_to_string(timeline: Timeline, animation: Animation, format: str, audio_path: str = "") -> str: ...
def export_to_file(path: _PathLike, timeline: Timeline, animation: Animation, format: str = "",
                   audio_path: str = "") -> None: ...
def timing_format_names() -> list[str]: ...
def read_timing_string(text: str, format: str, transcript: Timeline, duration_s: float = 0.0,
                       source_name: str = "<timing>") -> Timeline: ...
def read_timing_file(path: _PathLike, transcript: Timeline, duration_s: float = 0.0, format: str = "") -> Timeline: ...
def write_timing_string(timeline: Timeline, format: str) -> str: ...
def time_transcript(
    timing_path: _PathLike, audio_path: _PathLike, transcript: Timeline, format: str = "", options: AlignOptions | None = None
) -> Timeline: ...
def audio_duration_s(audio_path: _PathLike) -> float: ...
def is_valid_pinyin(syllable: str) -> bool: ...
def syllable_mouth_shapes(pinyin: str) -> list[MouthShape]: ...
def mandarin_syllables() -> list[str]: ...

class SentenceCutMode(enum.Enum):
    automatic = 0
    first_pause = 1

class CheckMode(enum.Enum):
    refuse = 0
    warn = 1
    off = 2

class AlignOptions:
    sentence_cut: SentenceCutMode
    first_pause_start_s: float
    first_pause_end_s: float
    c1: float
    c2: float
    check: CheckMode
    lenient: bool
    def __init__(
        self,
        sentence_cut: SentenceCutMode = ...,
        first_pause_start_s: float = 0.0,
        first_pause_end_s: float = 0.0,
        c1: float = 0.95,
        c2: float = 1.45,
        check: CheckMode = ...,
        lenient: bool = ...,
    ) -> None: ...

_Progress = Callable[[float, str], bool | None]

class SpeechAligner:
    def __init__(self, options: AlignOptions = ...) -> None: ...
    @property
    def options(self) -> AlignOptions: ...
    def align_file(self, path: _PathLike, transcript: Timeline, progress: _Progress | None = None) -> Timeline: ...
    def align(
        self,
        samples: numpy.typing.ArrayLike,
        sample_rate_hz: int,
        transcript: Timeline,
        progress: _Progress | None = None,
    ) -> Timeline: ...

def alignment_plot_svg(audio_path: _PathLike, timeline: Timeline) -> str: ...
def write_alignment_plot_svg(svg_path: _PathLike, audio_path: _PathLike, timeline: Timeline) -> None: ...

class MouthKeyFrame:
    time_s: float
    shape: MouthShape
    syllable: int | None
    def __init__(self, time_s: float = 0.0, shape: MouthShape = ..., syllable: int | None = None) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class MouthInterpolation(enum.Enum):
    linear = 0
    smooth = 1

class ShapeOnsetTable:
    two_shapes: list[float]
    three_shapes: list[float]
    four_shapes: list[float]
    def __init__(
        self,
        two_shapes: Sequence[float] = ...,
        three_shapes: Sequence[float] = ...,
        four_shapes: Sequence[float] = ...,
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class LipSyncOptions:
    fps: float
    rest_min_pause_s: float
    rest_transition_s: float
    interpolation: MouthInterpolation
    max_speed_mns0_per_s: float
    onsets: ShapeOnsetTable
    def __init__(
        self,
        fps: float = 25.0,
        rest_min_pause_s: float = 0.3,
        rest_transition_s: float = 0.1,
        interpolation: MouthInterpolation = ...,
        max_speed_mns0_per_s: float = 8.75,
        onsets: ShapeOnsetTable = ...,
    ) -> None: ...

def mouth_key_frames(timeline: Timeline, options: LipSyncOptions = ...) -> list[MouthKeyFrame]: ...
def mouth_frames(
    neutral: FaceModel, key_frames: list[MouthKeyFrame], frame_count: int, options: LipSyncOptions = ...
) -> list[MouthControls]: ...

class ExpressionEventKind(enum.Enum):
    blink = 0
    brows = 1
    tilt = 2
    turn = 3
    nod = 4

def expression_event_kind_name(kind: ExpressionEventKind) -> str: ...
def expression_event_kind_from_name(name: str) -> ExpressionEventKind: ...

class ExpressionEvent:
    kind: ExpressionEventKind
    start_s: float
    end_s: float
    amount: float
    def __init__(self, kind: ExpressionEventKind | str, start_s: float, end_s: float, amount: float) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class ExpressionStyle:
    name: str
    blink_interval_shape: int
    blink_interval_scale_s: float
    blink_duration_s: tuple[float, float]
    brows_interval_s: tuple[float, float]
    brows_duration_s: tuple[float, float]
    brows_amount: tuple[float, float]
    tilt_interval_s: tuple[float, float]
    tilt_duration_s: tuple[float, float]
    tilt_angle_deg: tuple[float, float]
    turn_interval_s: tuple[float, float]
    turn_duration_s: tuple[float, float]
    turn_angle_deg: tuple[float, float]
    nod_lead_s: tuple[float, float]
    nod_down_s: tuple[float, float]
    nod_up_s: tuple[float, float]
    nod_angle_deg: tuple[float, float]
    nod_min_pause_s: float
    is_blink_simulated: bool
    is_brows_simulated: bool
    is_tilt_simulated: bool
    is_turn_simulated: bool
    is_nod_simulated: bool
    def __init__(self, base: str = "normal") -> None: ...
    @staticmethod
    def normal() -> ExpressionStyle: ...
    @staticmethod
    def announcer() -> ExpressionStyle: ...
    @staticmethod
    def from_name(name: str) -> ExpressionStyle: ...
    @staticmethod
    def from_json(text: str, source: str = "<string>") -> ExpressionStyle: ...
    @staticmethod
    def load(path: str) -> ExpressionStyle: ...
    def to_json(self) -> str: ...
    def validate(self) -> None: ...
    def is_simulated(self, kind: ExpressionEventKind) -> bool: ...
    def set_simulated(self, kind: ExpressionEventKind, is_simulated: bool) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __ne__(self, other: object) -> bool: ...

class UserEventMode(enum.Enum):
    add = 0
    replace = 1

def validate_expression_events(events: list[ExpressionEvent]) -> None: ...
def timeline_end_s(timeline: Timeline) -> float: ...

class ExpressionSimulator:
    def __init__(self, timeline: Timeline, seed: int = 0, style: str | ExpressionStyle = "normal") -> None: ...
    @property
    def seed(self) -> int: ...
    @property
    def style(self) -> ExpressionStyle: ...
    @property
    def duration_s(self) -> float: ...
    def simulated_events(self) -> list[ExpressionEvent]: ...
    def events(self) -> list[ExpressionEvent]: ...
    def set_user_events(self, events: list[ExpressionEvent], mode: UserEventMode = ...) -> None: ...
    def pose_at(self, time_s: float) -> Pose: ...
    def expression_at(self, time_s: float) -> Expression: ...

class Animation:
    @property
    def fps(self) -> float: ...
    @property
    def duration_s(self) -> float: ...
    @property
    def mouth_key_frames(self) -> list[MouthKeyFrame]: ...
    @property
    def events(self) -> list[ExpressionEvent]: ...
    @property
    def frames(self) -> list[FaceState]: ...
    def __len__(self) -> int: ...
    def key_frames_json(self) -> str: ...
    def key_frames_tsv(self) -> str: ...

def animate(
    neutral: FaceModel,
    timeline: Timeline,
    expressions: ExpressionSimulator,
    options: LipSyncOptions = ...,
) -> Animation: ...
def key_frames_json(mouth_key_frames: list[MouthKeyFrame], events: list[ExpressionEvent], fps: float,
                    duration_s: float) -> str: ...
def key_frames_tsv(mouth_key_frames: list[MouthKeyFrame]) -> str: ...

class VideoFormat(enum.Enum):
    mp4 = 0
    webm = 1
    webp = 2
    png_sequence = 3
    gif = 4

def video_format_from_path(path: str) -> VideoFormat: ...

class VideoOptions:
    width_px: int
    height_px: int
    fps: float
    crf: int
    transparent: bool
    def __init__(self, width_px: int = 1280, height_px: int = 720, fps: float = 30.0, crf: int = -1,
                 transparent: bool = False) -> None: ...

def check_video_options(path: str, options: VideoOptions = ...) -> None: ...

class VideoWriter:
    def __init__(self, path: str, options: VideoOptions = ...) -> None: ...
    @property
    def format(self) -> VideoFormat: ...
    @property
    def options(self) -> VideoOptions: ...
    @property
    def frame_count(self) -> int: ...
    def add_audio(self, samples: numpy.typing.NDArray[numpy.float32], sample_rate_hz: int) -> None: ...
    def add_audio_file(self, audio_path: str) -> None: ...
    def write_frame(self, frame: numpy.typing.NDArray[numpy.uint8]) -> None: ...
    def finish(self) -> None: ...
    def __enter__(self) -> VideoWriter: ...
    def __exit__(self, exception_type: object, exception: object, traceback: object) -> bool: ...

class FaceVideoOptions:
    video: VideoOptions
    background: str | None
    background_image_path: str
    layout: FrameLayout
    face_origin_px: tuple[float, float] | None
    face_d_px: float
    look: FaceLook
    draw_clothes: bool
    clothes: str
    stroke_width_in_d: float
    def __init__(self, video: VideoOptions = ..., layout: FrameLayout = ..., background: str | None = "#1d3b5c",
                 background_image_path: str = "", face_origin_px: tuple[float, float] | None = None,
                 face_d_px: float = 0.0, look: FaceLook = ..., draw_clothes: bool = True,
                 clothes: str = "#2f4f7f", stroke_width_in_d: float = 0.025) -> None: ...

def render_video(path: str, face: FaceModel, animation: Animation, audio_path: str = "",
                 options: FaceVideoOptions = ...,
                 progress: _Progress | None = None) -> None: ...
