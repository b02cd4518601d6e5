"""docs/python.md's signatures (its "Signatures" block) are the module's: the same parameters in the same order,
the same keyword-only marker and defaults, and every public function, constructor and method is listed."""
import ast
import re

import contactbench as cb


def documented(source_dir):
    """{qualified name: signature line} of the python block under docs/python.md's "## Signatures"."""
    text = (source_dir / "docs" / "python.md").read_text(encoding="utf-8")
    section = text.split("\n## Signatures\n", 1)[1]
    block = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    lines = [line.split("  #")[0].strip() for line in block.splitlines()]
    lines = [line for line in lines if line and not line.startswith("#")]
    return {line[: line.index("(")]: line for line in lines}


def parameters(params):
    """(name, kind, default) of each parameter of "a: T = d, *, b" with the annotations dropped."""
    arguments = ast.parse(f"def f({params}): pass").body[0].args
    positional = arguments.posonlyargs + arguments.args
    defaults = [None] * (len(positional) - len(arguments.defaults)) + arguments.defaults
    found = [(a.arg, "positional", d) for a, d in zip(positional, defaults)]
    found += [(a.arg, "keyword", d) for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)]
    found = [(name, kind, ast.unparse(d) if d is not None else None) for name, kind, d in found]
    return [p for p in found if p[0] != "self"]


def callables():
    """{qualified name: (object, is a class)} of every public function, constructor and method."""
    found = {}
    for owner, prefix in [(cb, ""), (cb.paper, "paper.")]:
        for name in dir(owner):
            value = getattr(owner, name)
            if name.startswith("_") or name == "paper" or isinstance(value, type) and issubclass(value, Exception):
                continue
            if isinstance(value, type):
                init = vars(value).get("__init__")
                if init is not None and (init.__doc__ or "").startswith("__init__("):
                    found[prefix + name] = (value, True)
                for method, member in vars(value).items():
                    if not method.startswith("_") and type(member).__name__ == "instancemethod":
                        found[f"{prefix}{name}.{method}"] = (member, False)
            elif callable(value):
                found[prefix + name] = (value, False)
    return found


def module_parameters(make_stubs, qualified, value, is_class):
    if is_class:
        params = make_stubs.keyword_signature(value) if "**kwargs" in value.__init__.__doc__ else None
        if params is None:
            params = make_stubs.signatures("__init__", value.__init__.__doc__)[0][0]
    else:
        params = make_stubs.signatures(qualified.split(".")[-1], value.__doc__)[0][0]
    return parameters(params)


def test_every_callable_is_documented(source_dir):
    assert sorted(callables()) == sorted(documented(source_dir))


def test_documented_signatures_are_the_modules(source_dir, make_stubs):
    docs = documented(source_dir)
    wrong = []
    for qualified, (value, is_class) in callables().items():
        line = docs.get(qualified)
        if line is None:
            continue  # test_every_callable_is_documented names it
        written = parameters(line[line.index("(") + 1 : line.rindex(")")])
        actual = module_parameters(make_stubs, qualified, value, is_class)
        if written != actual:
            wrong.append(f"{line}\n    module: {actual}\n    docs:   {written}")
    assert not wrong, "\n".join(wrong)
