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
"""

from ._talkface import (
    AlignmentError,
    Cancelled,
    Error,
    ErrorCode,
    Expression,
    FaceColors,
    FaceModel,
    FaceState,
    FileError,
    InvalidArgument,
    LiftedFace,
    MouthControls,
    MouthShape,
    NoseBridgeSide,
    ParseError,
    Pose,
    ProjectedFace,
    Rotation3D,
    SvgAnimator,
    SvgOptions,
    __version__,
    additional_point_ids,
    all_mouth_shapes,
    apply_expression,
    apply_mouth,
    depth_in_d,
    kMaxPoseAngleDeg,
    lift_face,
    mouth_controls,
    mouth_shape_from_name,
    mouth_shape_name,
    neutral_mouth_controls,
    place_face,
    project_face,
    rotation_origin,
    to_image,
    to_local,
    version,
)


def default_face() -> FaceModel:
    """The built-in default face (same as FaceModel.default()).

    Example:
        >>> face = talkface.default_face()
        >>> face.fapu("d")
    """
    return FaceModel.default()


__all__ = [
    "AlignmentError",
    "Cancelled",
    "Error",
    "ErrorCode",
    "Expression",
    "FaceColors",
    "FaceModel",
    "FaceState",
    "FileError",
    "InvalidArgument",
    "LiftedFace",
    "MouthControls",
    "MouthShape",
    "NoseBridgeSide",
    "ParseError",
    "Pose",
    "ProjectedFace",
    "Rotation3D",
    "SvgAnimator",
    "SvgOptions",
    "__version__",
    "additional_point_ids",
    "all_mouth_shapes",
    "apply_expression",
    "apply_mouth",
    "default_face",
    "depth_in_d",
    "kMaxPoseAngleDeg",
    "lift_face",
    "mouth_controls",
    "mouth_shape_from_name",
    "mouth_shape_name",
    "neutral_mouth_controls",
    "place_face",
    "project_face",
    "rotation_origin",
    "to_image",
    "to_local",
    "version",
]
