#!/usr/bin/env python3
"""Writes the catalogue's non-UTF-8 presets (raw bytes an editor would not keep) and their
expectations. Run from anywhere; the files are committed, so this only documents how they were made."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HEAD = b'{\n  "format": "particle-lab-preset",\n  "version": 1,\n'
TAIL = (b'  "room": { "center": [0, 0, 0], "size": [10, 6, 10] },\n'
        b'  "particles": [ { "position": [0, 0, 0] } ]\n}\n')

CASES = [
    ('150_invalid_utf8_byte', HEAD + b'  "name": "ball \xff",\n' + TAIL,
     'not valid UTF-8 text: invalid byte 0xFF at line 4, column 17'),
    ('151_latin1_description', HEAD + b'  "description": "caf\xe9 experiment",\n' + TAIL,
     'not valid UTF-8 text: invalid byte 0xE9 at line 4, column 22'),
    ('152_overlong_utf8', HEAD + b'  "name": "\xc0\xaf",\n' + TAIL,
     'not valid UTF-8 text: invalid byte 0xC0'),
    ('153_utf8_encoded_surrogate', HEAD + b'  "name": "\xed\xa0\x80",\n' + TAIL,
     'not valid UTF-8 text: invalid byte 0xED'),
    ('154_utf8_cut_at_end', HEAD + b'  "name": "x",\n' + TAIL + b'\xe2\x82',
     'not valid UTF-8 text: invalid byte 0xE2'),
    ('155_utf16_file', ('{"format": "particle-lab-preset", "version": 1}').encode('utf-16'),
     'not valid UTF-8 text: invalid byte 0xFF at line 1, column 1'),
]

for name, data, expect in CASES:
    with open(os.path.join(HERE, name + '.json'), 'wb') as f:
        f.write(data)
    with open(os.path.join(HERE, name + '.expect'), 'w') as f:
        f.write(expect + '\n')
