"""What the live-embed tests of both browsers share (live_test.py in Chromium, live_firefox_test.py in
Firefox): making the lazy pictures load, and the verdict on an embed in a browser without WebGL."""

# Every picture of the page made to load now, not when scrolled to (the figures below the first screen
# are lazy, issue 50's page weight); a promise that settles once each is decoded or has failed.
LOAD_PICTURES = ("Promise.all([...document.images].map(i => { i.loading = 'eager'; "
                 "return i.decode().catch(() => null); })).then(() => true)")


def no_webgl_problems(states):
    """Without WebGL each embed (a dict with stage, state, note, button, imageShown) must say so, keep
    its picture and offer no start button; the problems, one line each."""
    return [f"without WebGL, {s['stage']}: state {s['state']}, note {s['note']!r}, "
            f"button shown {s['button']}, picture shown {s['imageShown']}"
            for s in states
            if s["state"] != "unavailable" or "WebGL2" not in s["note"] or s["button"] or not s["imageShown"]]
