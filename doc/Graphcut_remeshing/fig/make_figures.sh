#!/bin/sh
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Regenerates the pictures of the manual and the README from a build directory: fandisk and cow
# (CGAL's sample meshes) before and after `graphcut_remesh` with its defaults, and the histograms of
# their angles, all drawn by the package's own `render_mesh`. The remeshing is deterministic, so the
# files come out the same on one machine.
#
# usage: doc/Graphcut_remeshing/fig/make_figures.sh [BUILD_DIR]      (default: build)
#        BUILD_DIR must hold the tools: cmake --build BUILD_DIR --target graphcut_remesh render_mesh
set -eu

build=${1:-build}
fig=$(cd "$(dirname "$0")" && pwd)
remesh="$build/examples/graphcut_remesh"
render="$build/examples/render_mesh"
data="$build/data/meshes"
for f in "$remesh" "$render" "$data/fandisk.off" "$data/cow.off"; do
  if [ ! -e "$f" ]; then
    echo "make_figures.sh: $f not found; build the tools first:" >&2
    echo "  cmake --build $build --target graphcut_remesh render_mesh" >&2
    exit 1
  fi
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

# Each model seen from a direction that shows its features: fandisk's curved cuts and sharp
# edges, the cow's side (both have y up).
for model in fandisk cow; do
  case $model in
    fandisk) view="1 1 2" ;;
    cow) view="0.4 0.5 1" ;;
  esac
  echo "remeshing $model (defaults)"
  "$remesh" --quiet "$data/$model.off" "$tmp/$model.off"
  # shellcheck disable=SC2086  # $view is three numbers
  "$render" --size 720 --view $view --title "$model: input" "$data/$model.off" "$fig/${model}_input.svg"
  # shellcheck disable=SC2086
  "$render" --size 720 --view $view --title "$model: remeshed by graphcut_remesh (defaults)" \
    "$tmp/$model.off" "$fig/${model}_remeshed.svg"
  "$render" --histogram --title "$model: smallest angle of each triangle" --label input --label remeshed \
    "$data/$model.off" "$tmp/$model.off" "$fig/${model}_min_angles.svg"
  "$render" --histogram --all-angles --title "$model: all angles of the triangles" --label input --label remeshed \
    "$data/$model.off" "$tmp/$model.off" "$fig/${model}_all_angles.svg"
done
ls -l "$fig"/*.svg
