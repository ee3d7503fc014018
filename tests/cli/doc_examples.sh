#!/bin/bash
# Runs the command examples a new user meets: README.md's "Using it" block, docs/cli.md's
# `sh` blocks and `$ ` lines, and the "Examples:" of every command's --help. Each source runs
# in a scratch folder of its own that holds the bundled assets/ and golden/, so an example must
# use them or make what it needs first. Every example must exit 0.
#
# To keep it short, the `radiant` on PATH runs the examples smaller: a render or session that
# gives no size gets --width 32, a given --width or --height is held to 64 and --spp to 64;
# converge runs at 24 pixels wide at most (or a --reference's size), its default ladder stops at 16 spp, its reference
# at 64, and --supersampling measures the jittered sampler alone.
#
# Usage: doc_examples.sh RADIANT_EXE SOURCE_DIR
set -u
radiant_exe=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

mkdir "$scratch/bin"
cat > "$scratch/bin/radiant" <<EOF
#!/bin/bash
command=\${1-}
largest=64 width=32 args=() sized=0 ladder=0 reference=0
[[ \$command == converge ]] && largest=24 width=24
while ((\$#)); do
  case \$1 in
    --width|--height) sized=1; value=\$2; ((value > largest)) && value=\$largest; args+=("\$1" "\$value"); shift 2; continue ;;
    --spp) [[ \$command == render || \$command == session ]] && ((\$2 > 64)) && { args+=(--spp 64); shift 2; continue; } ;;
    --spp-ladder|--max-spp) ladder=1 ;;
    --supersampling) ladder=1; [[ " \$* " == *" --samplers "* ]] || args+=(--samplers jittered) ;;
    --reference) reference=1 sized=1 ;;  # the reference's size
    --reference-spp) reference=1 ;;
  esac
  args+=("\$1"); shift
done
case \$command in render|session|converge) ((sized)) || args+=(--width "\$width") ;; esac
[[ \$command == converge ]] && ((!ladder)) && args+=(--max-spp 16)
[[ \$command == converge ]] && ((!reference)) && args+=(--reference-spp 64)
exec "$radiant_exe" "\${args[@]}"
EOF
chmod +x "$scratch/bin/radiant"
export PATH="$scratch/bin:$PATH"

failures=0 count=0
# Runs each line of standard input (a trailing \ joins the next) in a fresh folder named $1.
run_examples() {
  local folder="$scratch/$1" line="" part
  mkdir "$folder" && ln -s "$source_dir/assets" "$folder/assets" && ln -s "$source_dir/golden" "$folder/golden"
  while IFS= read -r part; do
    if [[ $part == *\\ ]]; then line+="${part%\\}"; continue; fi
    line+="$part"
    if [[ -n ${line// /} ]]; then
      count=$((count + 1))
      local start=$SECONDS
      if ! (cd "$folder" && timeout 120 bash -c "set -o pipefail; $line" < /dev/null > "$scratch/out" 2> "$scratch/err"); then
        failures=$((failures + 1))
        echo "FAILED ($1): $line"
        sed 's/^/    /' "$scratch/err" | head -5
      fi
      ((SECONDS - start > 5)) && echo "slow ($1, $((SECONDS - start)) s): $line"
    fi
    line=""
  done
}

# README.md: the fenced block of "## Using it".
run_examples readme < <(awk '/^## /{section = $0} section == "## Using it" && /^```/{inside = !inside; next} inside' \
  "$source_dir/README.md")

# docs/cli.md: whole `sh` blocks, and the `$ ` lines of other blocks.
run_examples cli-md < <(awk '/^```sh/{block = "sh"; next} /^```/{block = (block == "" ? "text" : ""); next}
     block == "sh"{print} block == "text" && /^\$ /{print substr($0, 3)}' "$source_dir/docs/cli.md")

for command in render info compare converge batch merge session; do
  run_examples "help-$command" < <("$radiant_exe" "$command" --help | sed -n '/^Examples:/,/^$/p' | sed '1d; s/^  //')
done

echo "$((count - failures)) of $count examples ran as written"
((count > 0 && failures == 0))
