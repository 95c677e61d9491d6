# Sourced by the rooms' error-against-time scripts (sunlit_room_error_vs_time.sh,
# conference_error_vs_time.sh): the sweep they share.
#
# room_error_sweep BENCH CSV PNG TITLE BENCH_ARGS...
#   runs BENCH_ARGS through BENCH (bench_indirect_accuracy) at 5 and 10 cm texels and target
#   errors 0.2 / 0.1 / 0.05 (the defaults, 5 cm at 0.1, first with the CSV header), then plots
#   CSV into PNG with plot_lightmap_error.py under TITLE.
room_error_sweep() {
  local bench=$1 csv=$2 png=$3 title=$4
  shift 4
  "$bench" "$@" --texel-size 0.05 --target-error 0.1 --header > "$csv"
  for texel in 0.05 0.1; do
    for target in 0.2 0.1 0.05; do
      [ "$texel" = 0.05 ] && [ "$target" = 0.1 ] && continue
      "$bench" "$@" --texel-size "$texel" --target-error "$target" >> "$csv"
    done
  done
  /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/plot_lightmap_error.py" "$csv" "$png" "$title"
}
