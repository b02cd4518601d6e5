// C++ errors as Python exceptions, with the C++ message unchanged (the CLI prints the same text):
//   contactbench::Error      -> contactbench.Error       (a ValueError): bad argument or impossible request
//   contactbench::InputError -> contactbench.InputError  (an Error and an OSError): bad file content; the
//                               message reads "path:line: reason", and the attributes path and line say it
//                               too
//   contactbench::SceneError -> contactbench.SceneError  (an Error): a scene file's problems, one per entry
//   of
//                               the attribute problems
#include <functional>

#include "bindings.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench::python {

namespace {

PyObject* new_exception(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string qualified = std::string("contactbench.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::handle(type));  // the module keeps the reference
  return type;
}

void raise(PyObject* type, const std::string& message, const std::function<void(py::object&)>& decorate) {
  py::object exception = py::reinterpret_steal<py::object>(PyObject_CallFunction(type, "s", message.c_str()));
  if (!exception) return;  // the call set its own error
  decorate(exception);
  PyErr_SetObject(type, exception.ptr());
}

}  // namespace

void register_errors(py::module_& m) {
  static PyObject* error = new_exception(
      m, "Error", PyExc_ValueError,
      "A refused argument or impossible request; the message names the argument and the accepted "
      "values (the CLI's message).");
  const py::tuple input_bases = py::make_tuple(py::handle(error), py::handle(PyExc_OSError));
  static PyObject* input_error = new_exception(
      m, "InputError", input_bases.ptr(),
      "Bad content in a file: the message reads 'path:line: reason' (no line when the file as a "
      "whole is wrong). Attributes: path (str), line (int, 0 for the whole file). Also an "
      "OSError, so `except OSError` catches it with the other file errors.");
  const py::tuple scene_bases = py::make_tuple(py::handle(error));
  static PyObject* scene_error = new_exception(
      m, "SceneError", scene_bases.ptr(),
      "A scene file's problems, all of them: the message lists them one per line, the attribute "
      "problems (list of str) one per entry, each with its key path and the accepted values.");

  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      raise(input_error, e.what(), [&](py::object& x) {
        x.attr("path") = e.path().string();
        x.attr("line") = e.line();
      });
    } catch (const SceneError& e) {
      raise(scene_error, e.what(), [&](py::object& x) {
        py::list problems;
        for (const std::string& problem : e.problems())
          problems.append(problem);
        x.attr("problems") = problems;
      });
    } catch (const Error& e) {
      raise(error, e.what(), [](py::object&) {});
    }
  });
}

}  // namespace contactbench::python
