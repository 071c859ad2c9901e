#!/usr/bin/env python3
"""Runs a page in headless chromium and prints its clothlab status (window.clothlab) as JSON.

    page_run.py URL [--seconds S] [--until-done] [--screenshot FILE.png]

Chromium is driven over its DevTools protocol on a pipe (--remote-debugging-pipe: file descriptors 3
and 4, messages ending in NUL), so only the standard library is needed. It loads URL, polls
window.clothlab every 0.25 s for S seconds of wall time (default 10), or until its `done` is true
with --until-done, saves a screenshot and prints the last status with `console_errors`: every
console.error, uncaught exception and error logged by the browser (network errors included).
Chromium renders with SwiftShader (no GPU): --use-angle=swiftshader --enable-unsafe-swiftshader.
"""
import argparse, base64, json, os, subprocess, sys, tempfile, time

ap = argparse.ArgumentParser()
ap.add_argument("url")
ap.add_argument("--seconds", type=float, default=10.0)
ap.add_argument("--until-done", action="store_true")
ap.add_argument("--screenshot")
args = ap.parse_args()

to_chrome_r, to_chrome_w = os.pipe()
from_chrome_r, from_chrome_w = os.pipe()
profile = tempfile.mkdtemp(prefix="clothlab-chromium-")


def child_fds():
    os.dup2(to_chrome_r, 3)
    os.dup2(from_chrome_w, 4)


chrome = subprocess.Popen(
    ["chromium", "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
     "--remote-debugging-pipe", "--user-data-dir=" + profile, "--window-size=1280,800", "about:blank"],
    pass_fds=(3, 4, to_chrome_r, from_chrome_w), preexec_fn=child_fds, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
os.close(to_chrome_r)
os.close(from_chrome_w)
buf = b""
next_id = 0
errors = []


def handle(msg):
    m, p = msg.get("method"), msg.get("params", {})
    if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
        errors.append("console.error: " + " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
    elif m == "Runtime.exceptionThrown":
        d = p.get("exceptionDetails", {})
        errors.append("exception: " + d.get("exception", {}).get("description", d.get("text", "")))
    elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
        e = p["entry"]
        errors.append("browser (%s): %s %s" % (e.get("source"), e.get("text"), e.get("url", "")))


def call(method, params=None, session=None, timeout=60):
    global next_id, buf
    next_id += 1
    msg = {"id": next_id, "method": method, "params": params or {}}
    if session:
        msg["sessionId"] = session
    os.write(to_chrome_w, json.dumps(msg).encode() + b"\0")
    deadline = time.time() + timeout
    while time.time() < deadline:
        while b"\0" in buf:
            raw, buf = buf.split(b"\0", 1)
            reply = json.loads(raw)
            if reply.get("id") == next_id:
                if "error" in reply:
                    raise RuntimeError("%s: %s" % (method, reply["error"]))
                return reply.get("result", {})
            handle(reply)
        chunk = os.read(from_chrome_r, 1 << 20)
        if not chunk:
            raise RuntimeError("chromium closed the pipe")
        buf += chunk
    raise RuntimeError(method + ": no answer in %d s" % timeout)


status = {}
try:
    target = call("Target.createTarget", {"url": "about:blank"})["targetId"]
    s = call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    call("Runtime.enable", session=s)
    call("Log.enable", session=s)
    call("Page.enable", session=s)
    call("Page.navigate", {"url": args.url}, session=s)
    end = time.time() + args.seconds
    while time.time() < end:
        time.sleep(0.25)
        r = call("Runtime.evaluate", {"expression": "JSON.stringify(window.clothlab || null)", "returnByValue": True}, session=s)
        v = r.get("result", {}).get("value")
        status = json.loads(v) if v and v != "null" else status
        if args.until_done and status.get("done"):
            break
    if args.screenshot:
        png = call("Page.captureScreenshot", {"format": "png"}, session=s)["data"]
        with open(args.screenshot, "wb") as f:
            f.write(base64.b64decode(png))
    # The same status as the page mirrors into #clothlab-status (what --dump-dom would read).
    r = call("Runtime.evaluate", {"expression": "(document.getElementById('clothlab-status') || {}).textContent || ''",
                                  "returnByValue": True}, session=s)
    status["element_mirrors_status"] = bool(r.get("result", {}).get("value"))
finally:
    try:
        call("Browser.close", timeout=5)
    except Exception:
        pass
    chrome.wait(timeout=30)
    subprocess.run(["rm", "-rf", profile])
status["console_errors"] = status.get("console_errors", []) + errors
json.dump(status, sys.stdout)
print()
