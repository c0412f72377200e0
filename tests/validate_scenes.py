#!/usr/bin/env python3
"""Validates YAML scene files against drape's JSON Schema (`drape schema --json-schema`).

    validate_scenes.py SCHEMA.json SCENE.yaml...

Prints one line per scene, `ok PATH` or `invalid PATH: key.path: what`, and exits 0 when every
scene is valid, 1 when one is not, 2 when the schema itself is not a valid draft 2020-12 schema.
Used by tests/scene_json_schema_test.cc (python3-jsonschema and python3-yaml, both in Debian).

The YAML is read as YAML 1.2 reads numbers (what editors' YAML extensions do): PyYAML follows
YAML 1.1, where `1e-8` (no dot) is a string.
"""
import json
import re
import sys

import jsonschema
import yaml


class Yaml12Loader(yaml.SafeLoader):
    """SafeLoader with YAML 1.2's floats: 1e-8, 2E5, .5 as well as 1.0e-8."""


Yaml12Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$"),
    list("-+0123456789."),
)


def path_of(error):
    """The failing value's key path, as drape names it: `fixed[0].dofs`."""
    text = ""
    for part in error.absolute_path:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += ("." if text else "") + str(part)
    return text or "(top)"


def main(argv):
    with open(argv[1], encoding="utf-8") as file:
        schema = json.load(file)
    try:
        jsonschema.Draft202012Validator.check_schema(schema)
    except jsonschema.SchemaError as error:
        print(f"invalid schema: {error.message}")
        return 2
    validator = jsonschema.Draft202012Validator(schema)
    status = 0
    for path in argv[2:]:
        with open(path, encoding="utf-8") as file:
            scene = yaml.load(file, Loader=Yaml12Loader)
        errors = sorted(validator.iter_errors(scene), key=lambda e: [str(p) for p in e.absolute_path])
        if errors:
            status = 1
            print(f"invalid {path}: {path_of(errors[0])}: {errors[0].message}")
        else:
            print(f"ok {path}")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
