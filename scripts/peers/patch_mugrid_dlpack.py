#!/usr/bin/python3
"""Patches muGrid's Python bindings (language_bindings/python/bind_py_field.cc of muSpectre/muGrid 5b49579) so
that a host field's __dlpack__ also gives the legacy, unversioned DLPack capsule ("dltensor") when the consumer
asks for no max_version, as numpy < 2.1 does (Debian 12 has numpy 1.24, whose np.from_dlpack refuses muGrid's
"dltensor_versioned" capsule with "PyCapsule_GetPointer called with incorrect name"). The tensor is the same
(data, shape, strides, owner kept alive); consumers that pass max_version still get the versioned capsule.
numpy < 2.1 also marks what it imports by DLPack read-only (the legacy protocol has no flag for it), while
muGrid writes into these buffers: muGrid/Field.py is patched to view the same memory writeable (through
__array_interface__, the imported array kept alive as its base). Idempotent. Usage: patch_mugrid_dlpack.py SRC/muGrid (called by build_contactmechanics.sh)."""
import sys
from pathlib import Path

MARK = "contactbench peer build: legacy DLPack"
field_py = Path(sys.argv[1]) / "language_bindings" / "python" / "muGrid" / "Field.py"
field_text = field_py.read_text()
if MARK not in field_text:
    old_call = "self._buffer = np.from_dlpack(self._cpp)"
    helper = (
        "\n\n# " + MARK + ": numpy < 2.1 imports the legacy capsule read-only; view it writeable.\n"
        "class _WriteableView:\n"
        "    def __init__(self, array):\n"
        "        self._array = array\n"
        "        interface = dict(array.__array_interface__)\n"
        "        interface[\"data\"] = (interface[\"data\"][0], False)\n"
        "        self.__array_interface__ = interface\n\n\n"
        "def _writeable(array):\n"
        "    return array if array.flags.writeable else np.asarray(_WriteableView(array))\n\n\n")
    anchor = "\nclass "
    if field_text.count(old_call) != 1 or anchor not in field_text:
        sys.exit(f"patch_mugrid_dlpack: {field_py} is not the expected muGrid source")
    at = field_text.index(anchor)
    field_text = field_text[:at] + helper + field_text[at + 1:]
    field_text = field_text.replace(old_call, "self._buffer = _writeable(np.from_dlpack(self._cpp))")
    field_py.write_text(field_text)
    print(f"patch_mugrid_dlpack: patched {field_py}")

path = Path(sys.argv[1]) / "language_bindings" / "python" / "bind_py_field.cc"
text = path.read_text()
if MARK in text:
    sys.exit(0)

legacy = '''
// {mark}: the unversioned capsule for consumers that ask for no max_version (numpy < 2.1).
template<typename T, typename MemorySpace = muGrid::HostSpace>
void dlpack_deleter_legacy(DLManagedTensor* tensor) {{
    auto* ctx = static_cast<DLPackContext<T, MemorySpace>*>(tensor->manager_ctx);
    {{
        py::gil_scoped_acquire acquire;
        delete ctx;
    }}
    delete tensor;
}}

template<typename T, typename MemorySpace = muGrid::HostSpace>
py::capsule create_dlpack_capsule_legacy(TypedFieldBase<T, MemorySpace>& field, py::object owner) {{
    auto& coll = field.get_collection();
    if (!coll.is_initialised()) {{
        throw RuntimeError("Field collection isn't initialised yet");
    }}
    auto iter_unit = muGrid::IterUnit::SubPt;
    Shape_t shape = field.get_shape(iter_unit);
    Shape_t strides = field.get_strides(iter_unit, 1);
    auto* ctx = new DLPackContext<T, MemorySpace>(&field, std::move(owner), shape, strides);
    auto* managed = new DLManagedTensor();
    managed->manager_ctx = ctx;
    managed->deleter = dlpack_deleter_legacy<T, MemorySpace>;
    auto& tensor = managed->dl_tensor;
    tensor.data = field.get_void_data_ptr(false);
    tensor.device = DLDevice{{static_cast<DLDeviceType>(field.get_dlpack_device_type()), field.get_device_id()}};
    tensor.ndim = static_cast<int32_t>(shape.size());
    tensor.dtype = get_dlpack_dtype<T>();
    tensor.shape = ctx->shape.data();
    tensor.strides = ctx->strides.data();
    tensor.byte_offset = 0;
    auto capsule = py::capsule(managed, "dltensor");
    PyCapsule_SetDestructor(capsule.ptr(), [](PyObject* obj) {{
        const char* name = PyCapsule_GetName(obj);
        if (name != nullptr && std::strcmp(name, "dltensor") == 0) {{
            auto* unused = static_cast<DLManagedTensor*>(PyCapsule_GetPointer(obj, name));
            if (unused && unused->deleter) {{
                unused->deleter(unused);
            }}
        }}
    }});
    return capsule;
}}

'''.format(mark=MARK)

anchor = "void add_field(py::module &mod) {"
old_lambda = '''                [](py::object self_obj, py::object stream) {
                    (void)stream;  // Stream parameter not used for CPU tensors
                    auto &self = self_obj.cast<TypedFieldBase<T> &>();
                    return create_dlpack_capsule(self, self_obj);
                },'''
new_lambda = '''                [](py::object self_obj, py::object stream, py::kwargs kwargs) {
                    (void)stream;  // Stream parameter not used for CPU tensors
                    auto &self = self_obj.cast<TypedFieldBase<T> &>();
                    if (!kwargs.contains("max_version") || kwargs["max_version"].is_none()) {
                        return create_dlpack_capsule_legacy(self, self_obj);
                    }
                    return create_dlpack_capsule(self, self_obj);
                },'''
if text.count(anchor) != 1 or text.count(old_lambda) != 1:
    sys.exit(f"patch_mugrid_dlpack: {path} is not the expected muGrid source (anchor or __dlpack__ not found)")
text = text.replace(anchor, legacy + anchor).replace(old_lambda, new_lambda)
path.write_text(text)
print(f"patch_mugrid_dlpack: patched {path}")
