"""The web stages in the site (issue 36): what `make web` built into out/web/<stage>/ (index.html and
its .js, .wasm and .data), their download sizes, and the time to the first frame that
measure_web.py measured in headless Chromium. build_site.py writes web_data()'s result as
_data/web.json (live.html and live-summary.html read it) and copies the stages into the built site
under web/ with copy_stages().

A measurement counts only for the files it measured: each stage's measurement carries a fingerprint
(SHA-256 of its files), and a stage rebuilt since is shown without a time ("not measured").
"""

import gzip
import hashlib
import json
import os
import shutil


class WebError(Exception):
    pass


def stage_files(folder):
    """The files of one web stage, relative to its folder, sorted (subfolders included)."""
    out = []
    for root, dirs, names in os.walk(folder):
        dirs.sort()
        for name in sorted(names):
            out.append(os.path.relpath(os.path.join(root, name), folder).replace(os.sep, "/"))
    return out


def fingerprint(folder):
    digest = hashlib.sha256()
    for rel in stage_files(folder):
        digest.update(rel.encode() + b"\0")
        with open(os.path.join(folder, rel), "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                digest.update(chunk)
    return digest.hexdigest()


def megabytes(size):
    return f"{size / 1e6:.1f} MB" if size >= 1e5 else f"{size / 1e3:.0f} kB"


def sizes(folder):
    """(bytes on disk, bytes gzip-compressed at level 6: what a server that compresses sends)."""
    total = packed = 0
    for rel in stage_files(folder):
        with open(os.path.join(folder, rel), "rb") as f:
            data = f.read()
        total += len(data)
        packed += len(gzip.compress(data, compresslevel=6, mtime=0))
    return total, packed


def available(web_dir, names):
    """The stages of `names` that have a built page in web_dir."""
    if not web_dir or not os.path.isdir(web_dir):
        return []
    return [n for n in names if os.path.isfile(os.path.join(web_dir, n, "index.html"))]


def read_measurements(path):
    if not path or not os.path.isfile(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as error:
        raise WebError(f"{path}: cannot read the measurements: {error}")
    if not isinstance(data, dict) or not isinstance(data.get("stages"), dict):
        raise WebError(f"{path}: not a measurement file of measure_web.py (no 'stages')")
    return data


def web_data(web_dir, names, measurements_path, log):
    """_data/web.json: per stage with a web page its size and measured first-frame time."""
    built = available(web_dir, names)
    measured = read_measurements(measurements_path) if built else None
    data = {"stages": {}, "rows": [], "machine": {}, "measured_any": False}
    if measured:
        data["machine"] = {k: str(measured.get(k, "")) for k in ("browser", "renderer", "cpu", "date", "note", "size", "runs")}
    for name in built:
        folder = os.path.join(web_dir, name)
        total, packed = sizes(folder)
        entry = {"bytes": total, "gzip_bytes": packed, "size_text": megabytes(total),
                 "gzip_text": megabytes(packed), "files": len(stage_files(folder)),
                 "first_frame_ms": None, "first_frame_text": "not measured", "measured_text": "", "runs": []}
        m = (measured or {}).get("stages", {}).get(name)
        if m and m.get("fingerprint") == fingerprint(folder) and m.get("median_ms") is not None:
            entry["first_frame_ms"] = int(m["median_ms"])
            entry["runs"] = [int(v) for v in m.get("runs_ms", [])]
            entry["first_frame_text"] = f"{entry['first_frame_ms'] / 1000:.1f} s"
            renderer = data["machine"].get("renderer") or "an unnamed renderer"
            if "SwiftShader" in renderer or "llvmpipe" in renderer:
                renderer = ("SwiftShader" if "SwiftShader" in renderer else "Mesa's llvmpipe") + " (WebGL drawn on the CPU)"
            entry["measured_text"] = (f"When the site was built: first frame {entry['first_frame_text']} "
                                      f"after opening the page, in headless Chromium with {renderer}.")
            data["measured_any"] = True
        elif m:
            entry["measured_text"] = "Not measured for this build (the stage changed since): make site measures it."
        data["stages"][name] = entry
        data["rows"].append(dict(entry, stage=name))
        first = entry["first_frame_text"]
        log(f"web: {name}: {entry['size_text']} ({entry['gzip_text']} gzip-compressed, {entry['files']} files), "
            f"first frame {first}")
    if web_dir and not built:
        log(f"web: no web stages in {web_dir} (make web builds them): the pages show still pictures only")
    return data


def copy_stages(web_dir, names, dest):
    """Copies each built stage into DEST/web/<stage>/ (after jekyll, which empties DEST first), and the
    shader editor the stage pages open with ?edit=1 (WEB/editor/, cmake/T10Web.cmake) into DEST/web/editor/."""
    stages = available(web_dir, names)
    for name in stages + (["editor"] if stages and os.path.isdir(os.path.join(web_dir, "editor")) else []):
        target = os.path.join(dest, "web", name)
        if os.path.isdir(target):
            shutil.rmtree(target)
        shutil.copytree(os.path.join(web_dir, name), target)
