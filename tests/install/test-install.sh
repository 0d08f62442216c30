#!/usr/bin/env bash
# test_install: `cmake --install` into a fresh prefix, then the installed programs run from
# there: `hsmu run paper-condition-3` (in hsmu-cli) and of its file (in hsmu itself, no Qt
# loaded, the same steps.csv), `hsmu-controller --config paper-condition-3` (a preset
# name, found under PREFIX/share/hsmu/presets). With dpkg-deb, the .deb made by
# `cpack -G DEB` is unpacked into a fresh root and its hsmu runs the same test. When the build
# has the Python module (python/), `import hsmu` works from both in a fresh environment
# (only PYTHONPATH set to PREFIX/lib/python3/dist-packages) and runs the preset found under
# PREFIX/share/hsmu/presets.
# usage: test-install.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work/home"
export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config" XDG_DATA_HOME="$work/home/.local/share"
export QT_QPA_PLATFORM=offscreen

check_tree() { # PREFIX
    for f in bin/hsmu bin/hsmu-cli bin/hsmu-console bin/hsmu-controller share/hsmu/presets/paper-condition-3.json \
             share/hsmu/translations/hsmu_es.qm share/hsmu/translations/hsmu_zh_CN.qm \
             share/applications/hsmu.desktop share/icons/hicolor/scalable/apps/hsmu.svg \
             share/doc/hsmu/console.md; do
        [ -e "$1/$f" ] || { echo "FAIL: $1/$f is not installed"; exit 1; }
    done
}

run_test() { # PREFIX
    (cd "$work" && "$1/bin/hsmu" run paper-condition-3 --out "$work/out-$(basename "$(dirname "$1")")" > "$work/run.log" 2>&1) ||
        { cat "$work/run.log"; echo "FAIL: $1/bin/hsmu run paper-condition-3"; exit 1; }
    echo "ok: $1/bin/hsmu run paper-condition-3: $(tail -1 "$work/run.log")"
    # a file runs in hsmu itself, without Qt (gui/cli/FastRun.h); the preset above in hsmu-cli
    local file="$1/share/hsmu/presets/paper-condition-3.json"
    (cd "$work" && LD_DEBUG=files "$1/bin/hsmu" run "$file" --out "$work/file-out" > "$work/run.log" 2>&1) ||
        { cat "$work/run.log"; echo "FAIL: $1/bin/hsmu run $file"; exit 1; }
    if grep -q libQt6 "$work/run.log"; then echo "FAIL: $1/bin/hsmu run FILE loaded Qt"; exit 1; fi
    cmp "$work/file-out/steps.csv" "$work/out-$(basename "$(dirname "$1")")/steps.csv" ||
        { echo "FAIL: $1/bin/hsmu run FILE and PRESET wrote different steps.csv"; exit 1; }
    rm -rf "$work/file-out"
    echo "ok: $1/bin/hsmu run $file without Qt, the same steps.csv"
}

python_module=$(ls "$build"/python/hsmu.*.so 2> /dev/null | head -1 || true)
python_test() { # PREFIX
    [ -n "$python_module" ] || return 0
    local site="$1/lib/python3/dist-packages"
    ls "$site"/hsmu.*.so > /dev/null 2>&1 || { echo "FAIL: $site/hsmu.*.so is not installed"; exit 1; }
    (cd "$work" && env -i HOME="$HOME" PATH=/usr/bin:/bin PYTHONPATH="$site" /usr/bin/python3 -c \
        "import hsmu, os; assert os.path.dirname(hsmu.__file__) == '$site', hsmu.__file__; print(hsmu.__version__); r = hsmu.run('paper-condition-3'); assert r['status'] == 'finished', r['status']; print(len(r['steps']['time_s']), 'steps')" \
        > "$work/python.log" 2>&1) || { cat "$work/python.log"; echo "FAIL: import hsmu from $site"; exit 1; }
    echo "ok: import hsmu from $site: $(tr '\n' ' ' < "$work/python.log")"
}

prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
check_tree "$prefix"
if command -v desktop-file-validate > /dev/null; then
    desktop-file-validate "$prefix/share/applications/hsmu.desktop"
fi
run_test "$prefix"
python_test "$prefix"

# The controller takes a preset name (resolved next to the installed program).
"$prefix/bin/hsmu-controller" --config paper-condition-3 --port 0 --quiet \
    > "$work/controller.out" 2> "$work/controller.err" &
pid=$!
for _ in $(seq 1 100); do
    grep -q listening "$work/controller.out" 2> /dev/null && break
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
done
if ! grep -q listening "$work/controller.out"; then
    cat "$work/controller.err"; kill "$pid" 2> /dev/null || true
    echo "FAIL: hsmu-controller --config paper-condition-3 did not start"; exit 1
fi
kill "$pid"
wait "$pid" 2> /dev/null || true
echo "ok: hsmu-controller --config paper-condition-3: $(head -1 "$work/controller.out")"

if command -v dpkg-deb > /dev/null && command -v cpack > /dev/null; then
    (cd "$build" && cpack -G DEB -B "$work/package" > "$work/cpack.log" 2>&1) ||
        { cat "$work/cpack.log"; echo "FAIL: cpack -G DEB"; exit 1; }
    deb=$(ls "$work"/package/hsmu_*.deb)
    dpkg-deb --info "$deb" | grep -E "Package|Version|Depends"
    dpkg-deb -x "$deb" "$work/root"
    check_tree "$work/root/usr"
    run_test "$work/root/usr"
    python_test "$work/root/usr"
fi
echo "PASS"
