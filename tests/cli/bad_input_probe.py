"""Reads one file through the C ABI (ctypes) or the Python module, in a process of its own so that a
crash is seen as one, and prints {"status": "ok" | "error", "message": ...} as JSON (with "warnings",
the result's, where it is ok).

    bad_input_probe.py c|python audio|transcript|face FILE [TRANSCRIPT]

audio: aligns FILE with TRANSCRIPT; transcript: loads FILE; face: loads FILE.
"""

import ctypes
import json
import os
import sys


def through_c(kind, path, transcript_path):
    lib = ctypes.CDLL(os.environ["TALKFACE_C_LIBRARY"])
    lib.tf_last_error_message.restype = ctypes.c_char_p
    lib.tf_status_name.restype = ctypes.c_char_p
    handle = ctypes.c_void_p()
    if kind == "face":
        status = lib.tf_face_model_load(path.encode(), ctypes.byref(handle))
        release = lib.tf_face_model_destroy
    elif kind == "transcript":
        status = lib.tf_load_transcript(path.encode(), ctypes.byref(handle))
        release = lib.tf_timeline_destroy
    else:
        transcript = ctypes.c_void_p()
        if lib.tf_load_transcript(transcript_path.encode(), ctypes.byref(transcript)) != 0:
            raise RuntimeError(lib.tf_last_error_message().decode())
        status = lib.tf_align_file(path.encode(), transcript, None, None, None, ctypes.byref(handle))
        lib.tf_timeline_destroy(transcript)
        release = lib.tf_timeline_destroy
    if status != 0:
        name = lib.tf_status_name(status).decode()
        return {"status": "error", "type": name, "message": lib.tf_last_error_message().decode()}
    warnings = []
    if kind != "face":
        count = ctypes.c_size_t()
        lib.tf_timeline_warning_count(handle, ctypes.byref(count))
        for i in range(count.value):
            warning = ctypes.c_char_p()
            lib.tf_timeline_warning(handle, ctypes.c_size_t(i), ctypes.byref(warning))
            warnings.append(warning.value.decode())
    release(handle)
    return {"status": "ok", "warnings": warnings}


def through_python(kind, path, transcript_path):
    import talkface

    warnings = []
    try:
        if kind == "face":
            talkface.FaceModel.load(path)
        elif kind == "transcript":
            warnings = list(talkface.load_transcript(path).warnings)
        else:
            warnings = list(talkface.SpeechAligner().align_file(path, talkface.load_transcript(transcript_path)).warnings)
    except talkface.Error as error:
        return {"status": "error", "type": type(error).__name__, "message": str(error)}
    return {"status": "ok", "warnings": warnings}


if __name__ == "__main__":
    interface, kind, path = sys.argv[1:4]
    transcript_path = sys.argv[4] if len(sys.argv) > 4 else None
    probe = through_c if interface == "c" else through_python
    print(json.dumps(probe(kind, path, transcript_path)))
