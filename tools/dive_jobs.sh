# Sourced by tools/dive.sh and tools/dive-default.sh: runs "name:command" jobs, at most $jobs at a time,
# each logging to $log_dir/<name>.log; stops the script on the first failure (printing that log's end).
#   jobs=2 log_dir=out start_s=$SECONDS; run_jobs "a:cmd1" "b:cmd2" ...
run_jobs() {
  local pids=() names=()
  for spec in "$@"; do
    local name="${spec%%:*}" cmd="${spec#*:}"
    echo "   started $name"
    bash -c "$cmd" >"$log_dir/$name.log" 2>&1 &
    pids+=($!)
    names+=("$name")
    if [ "${#pids[@]}" -ge "$jobs" ]; then
      wait_jobs; pids=(); names=()
    fi
  done
  wait_jobs
}
wait_jobs() {
  for i in "${!pids[@]}"; do
    if ! wait "${pids[$i]}"; then
      echo "${names[$i]} failed; its log:" >&2
      tail -20 "$log_dir/${names[$i]}.log" >&2
      exit 1
    fi
    echo "   done ${names[$i]} ($((SECONDS - start_s)) s)"
  done
}
