#!/usr/bin/env python3
"""Fills a Qt .ts file from a glossary (JSON: {context: {source: translation}}).

A message with plural forms (%n) takes a list: one text per plural form of the language.

Maintainers' tool, not part of the build: after `cmake --build build --target
update_translations` adds new source texts, add their translations to
translations/glossary_<lang>.json and run
    python3 translations/tools/fill_ts.py translations/microsim_de.ts translations/glossary_de.json \
        translations/glossary/*_de.json
(translations/glossary/<part>_<lang>.json keeps each part's texts apart, so that people
working on different screens do not edit one file.)
Entries without a glossary translation stay unfinished, which the translation test reports.
"""
import json
import sys
import xml.etree.ElementTree as ET


def load_glossaries(paths: list[str]) -> dict:
    """Merges several glossaries (one per part of the app) context by context."""
    merged: dict = {}
    for path in paths:
        with open(path, encoding="utf-8") as f:
            for context, table in json.load(f).items():
                merged.setdefault(context, {}).update(table)
    return merged


def main(ts_path: str, glossary_paths: list[str]) -> int:
    glossary = load_glossaries(glossary_paths)
    tree = ET.parse(ts_path)
    missing = 0
    for context in tree.getroot().iter("context"):
        name = context.find("name").text
        table = glossary.get(name, {})
        for message in context.iter("message"):
            source = message.find("source").text
            translation = message.find("translation")
            if source in table:
                value = table[source]
                if message.get("numerus") == "yes":
                    # plural forms: the glossary gives a list, one entry per form of the language
                    for child in list(translation):
                        translation.remove(child)
                    translation.text = None
                    forms = value if isinstance(value, list) else [value]
                    for form in forms:
                        ET.SubElement(translation, "numerusform").text = form
                else:
                    translation.text = value
                translation.attrib.pop("type", None)
            elif translation.get("type") == "unfinished":
                missing += 1
                print(f"{ts_path}: no translation for [{name}] {source!r}", file=sys.stderr)
    tree.write(ts_path, encoding="utf-8", xml_declaration=True)
    return 1 if missing else 0


if __name__ == "__main__":
    if len(sys.argv) < 3:
        print("usage: fill_ts.py FILE.ts GLOSSARY.json [GLOSSARY.json ...]", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2:]))
