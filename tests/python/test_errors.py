import pytest

import talkface

BROKEN_XML = '<?xml version="1.0"?>\n<face version="1">\n  <point id="3.2" x="1"\n'


def test_hierarchy_maps_to_builtin_exceptions():
    assert issubclass(talkface.Error, RuntimeError)
    for error_class in (talkface.ParseError, talkface.FileError, talkface.InvalidArgument,
                        talkface.AlignmentError, talkface.Cancelled):
        assert issubclass(error_class, talkface.Error)
    assert issubclass(talkface.FileError, OSError)
    assert issubclass(talkface.InvalidArgument, ValueError)
    assert int(talkface.ErrorCode.parse) == 3  # equal to the C ABI's TF_ERR_PARSE


def test_parse_error_names_file_line_and_column(tmp_path):
    with pytest.raises(talkface.ParseError, match="face.xml:3:") as raised:
        talkface.FaceModel.from_xml(BROKEN_XML, "face.xml")
    error = raised.value
    assert error.code == talkface.ErrorCode.parse
    assert (error.path, error.line) == ("face.xml", 3)
    assert error.column > 0
    assert isinstance(error.item, str)

    path = tmp_path / "face.xml"
    path.write_text(BROKEN_XML, encoding="utf-8")
    with pytest.raises(talkface.ParseError, match="face.xml:3:") as raised:
        talkface.FaceModel.load(path)
    assert raised.value.path == str(path)


def test_missing_file_is_a_file_error_and_an_os_error(tmp_path):
    path = tmp_path / "missing.xml"
    with pytest.raises(OSError) as raised:
        talkface.FaceModel.load(path)
    error = raised.value
    assert isinstance(error, talkface.FileError)
    assert error.filename == str(path)
    assert str(path) in str(error)
    assert error.code == talkface.ErrorCode.file


def test_invalid_argument_names_the_parameter(face):
    with pytest.raises(ValueError, match='point "8.5"') as raised:
        face.point("8.5")
    assert raised.value.parameter == 'point "8.5"'
    assert raised.value.code == talkface.ErrorCode.invalid_argument
    with pytest.raises(talkface.InvalidArgument, match='FAPU "MW0"'):
        face.set_fapu("MW0", -1.0)


def test_errors_can_be_raised_from_python():
    with pytest.raises(talkface.Error, match="by hand"):
        raise talkface.Cancelled("stopped by hand")
    assert talkface.Cancelled.code == talkface.ErrorCode.cancelled


def test_version_matches_the_loaded_library():
    assert talkface.__version__ == talkface.version()
