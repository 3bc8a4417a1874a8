// talkface's exceptions in Python: ErrorCode, and one Python class per C++ error class, with the
// C++ fields as attributes. The translator below is the only place C++ errors become Python ones.
#include <exception>

#include "bind.hpp"

namespace talkface::python {

namespace {

// The Python classes, alive as long as the process (the module is never unloaded).
struct ErrorClasses {
    py::handle error;
    py::handle parse_error;
    py::handle file_error;
    py::handle invalid_argument;
    py::handle alignment_error;
    py::handle cancelled;
};

ErrorClasses& error_classes() {
    static ErrorClasses classes;
    return classes;
}


py::handle new_error_class(py::module_& m, const char* name, const char* doc, py::tuple bases, ErrorCode code,
                           py::dict extra = py::dict()) {
    extra["code"] = py::cast(code);
    PyObject* type =
        PyErr_NewExceptionWithDoc((std::string("talkface.") + name).c_str(), doc, bases.ptr(), extra.ptr());
    if (type == nullptr) throw py::error_already_set();
    m.add_object(name, py::handle(type));  // the module takes its own reference
    return py::handle(type);               // ours is kept for the process's lifetime
}

void raise(py::handle type, const Error& error, const py::dict& fields = py::dict()) {
    py::object instance = type(talkface::full_message(error));
    instance.attr("code") = py::cast(error.code());
    for (const auto& field : fields) instance.attr(field.first) = field.second;
    PyErr_SetObject(type.ptr(), instance.ptr());
}

void translate(std::exception_ptr thrown) {
    const ErrorClasses& classes = error_classes();
    try {
        if (thrown) std::rethrow_exception(thrown);
    } catch (const ParseError& error) {
        py::dict fields;
        fields["path"] = error.path();
        fields["line"] = error.line();
        fields["column"] = error.column();
        fields["item"] = error.item();
        raise(classes.parse_error, error, fields);
    } catch (const FileError& error) {
        py::dict fields;
        fields["filename"] = error.path();
        raise(classes.file_error, error, fields);
    } catch (const InvalidArgument& error) {
        py::dict fields;
        fields["parameter"] = error.parameter();
        raise(classes.invalid_argument, error, fields);
    } catch (const AlignmentError& error) {
        raise(classes.alignment_error, error);
    } catch (const Cancelled& error) {
        raise(classes.cancelled, error);
    } catch (const Error& error) {
        raise(classes.error, error);
    }
}

}  // namespace

void bind_errors(py::module_& m) {
    py::enum_<ErrorCode>(m, "ErrorCode", py::arithmetic(), R"doc(
What kind of failure a talkface.Error is; the values equal the C ABI's tf_status.

Example:
    >>> int(talkface.ErrorCode.parse)
    3
)doc")
        .value("invalid_argument", ErrorCode::invalid_argument, "a value passed is out of range or malformed")
        .value("file", ErrorCode::file, "a file could not be opened, read, written or renamed")
        .value("parse", ErrorCode::parse, "a file or string was read but its content is wrong")
        .value("alignment", ErrorCode::alignment, "audio and transcript cannot be matched")
        .value("cancelled", ErrorCode::cancelled, "a progress callback asked to stop")
        .value("out_of_memory", ErrorCode::out_of_memory, "an allocation failed")
        .value("internal", ErrorCode::internal, "a bug in talkface");

    ErrorClasses& classes = error_classes();
    classes.error = new_error_class(m, "Error", R"doc(
Base of every talkface error (C++ talkface::Error). str(error) is the full message, naming the file,
line, point, parameter or time that was wrong; .code is a talkface.ErrorCode.
)doc",
                                    py::make_tuple(py::handle(PyExc_RuntimeError)), ErrorCode::internal);

    classes.parse_error = new_error_class(m, "ParseError", R"doc(
A file or string was read but its content is wrong: "face.xml:12:5: point "8.3": ...".
Attributes: .path (file, or "<string>"), .line and .column (1-based, 0 if unknown), .item (e.g.
'point "8.3"', may be empty).
)doc",
                                          py::make_tuple(classes.error), ErrorCode::parse);

    // OSError.__str__ would print "[Errno None] None: 'path'" once .filename is set; keep our message.
    py::dict file_error_dict;
    file_error_dict["__str__"] = py::handle(PyExc_BaseException).attr("__str__");
    classes.file_error = new_error_class(m, "FileError", R"doc(
A file could not be opened, read, written or renamed. Also an OSError, so `except OSError` catches it;
.filename is the path, str(error) names it with the OS reason.
)doc",
                                         py::make_tuple(classes.error, py::handle(PyExc_OSError)),
                                         ErrorCode::file, file_error_dict);

    classes.invalid_argument = new_error_class(m, "InvalidArgument", R"doc(
A value passed is out of range or malformed. Also a ValueError; .parameter names the argument, option
or item that was wrong (e.g. "beta_deg", "points", 'FAPU "MW0"').
)doc",
                                               py::make_tuple(classes.error, py::handle(PyExc_ValueError)),
                                               ErrorCode::invalid_argument);

    classes.alignment_error = new_error_class(m, "AlignmentError", R"doc(
Audio and transcript cannot be matched (a missing sentence, the wrong text, a text that lacks its
last words).
)doc",
                                              py::make_tuple(classes.error), ErrorCode::alignment);

    classes.cancelled = new_error_class(m, "Cancelled", R"doc(
A progress callback asked to stop; nothing was written.
)doc",
                                        py::make_tuple(classes.error), ErrorCode::cancelled);

    py::register_exception_translator(translate);
}

}  // namespace talkface::python
