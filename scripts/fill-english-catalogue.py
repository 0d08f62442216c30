#!/usr/bin/env python3
"""Complete the English source catalogue: each translation is its source text.

Usage: fill-english-catalogue.py translations/hsmu_en.ts
"""
import sys
import xml.etree.ElementTree as ET


def fill(path):
    tree = ET.parse(path)
    for message in tree.getroot().iter("message"):
        source = message.find("source").text or ""
        translation = message.find("translation")
        translation.attrib.pop("type", None)
        forms = translation.findall("numerusform")
        if message.get("numerus") == "yes":
            for form in forms or [ET.SubElement(translation, "numerusform")]:
                form.text = source
        else:
            translation.text = source
    with open(path, "wb") as out:
        out.write(b'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        tree.write(out, encoding="utf-8", xml_declaration=False)
        out.write(b"\n")


if __name__ == "__main__":
    for p in sys.argv[1:]:
        fill(p)
