#!/usr/bin/env bash
# The architecture's rules (docs/architecture.md), checked on the source tree:
#  1. a folder includes only the folders before it in the layer order;
#  2. typed_*.h headers are included only inside their own folder;
#  3. no bare std::abort() (USVID_CHECK instead, core/check.h);
#  4. nothing cites a document outside the repository for its meaning;
#  5. a method's name is spelled, as a string, in at most two source files (its registration and
#     its implementation; docs/adding-a-method.md);
#  6. every option a method declares (methods/method_options.h) is read by a method: an option
#     declared and never read would be accepted and silently ignored. (Identify checks the same
#     at run time, after every fit: MethodOptions::Unread.)
#  7. model.json's keys are read through core/model_view.h (ModelView) and nowhere else: a method
#     writes its model, every reader takes it through the view;
#  8. no function body is longer than 80 lines (from the line after its opening brace to the line
#     before its closing one), measured with Universal Ctags, which gives each function's first
#     and last line (tools/install-deps.sh --test installs it).
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
layers=(core plot importers maneuvers simulators effects sensors simulation preprocessing methods
        metrics diagnosis design harness python apps)
sources=(core plot importers maneuvers simulators effects sensors simulation preprocessing methods
         metrics diagnosis design harness python apps bench fuzz tools)
fail=0

for ((i = 0; i < ${#layers[@]}; i++)); do
  folder=${layers[i]}
  allowed=" ${layers[*]:0:i} $folder "
  while IFS= read -r line; do
    file=${line%%:*}
    used=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$line")
    if [[ $allowed != *" $used "* ]]; then
      echo "layer: $file includes $used/, which comes after $folder/ (docs/architecture.md)"
      fail=1
    fi
  done < <(grep -rHE '^#include "[a-z_]+/' "$folder" --include='*.h' --include='*.cc' || true)
done

while IFS= read -r header; do
  folder=$(dirname "$header")
  while IFS= read -r user; do
    if [[ $(dirname "$user") != "$folder" ]]; then
      echo "interface: $user includes $header, internal to $folder/"
      fail=1
    fi
  done < <(grep -rlF "#include \"$header\"" "${sources[@]}" tests --include='*.h' --include='*.cc' || true)
done < <(find "${layers[@]}" -name 'typed_*.h' | sort)

if grep -rnF 'std::abort()' "${sources[@]}" --include='*.h' --include='*.cc' | grep -v '^core/check.cc:'; then
  echo "abort: use USVID_CHECK(condition, reason) (core/check.h)"
  fail=1
fi

if grep -rnE 'domain\.md|contract section|contract\.md' "${sources[@]}" tests docs README.md \
     --include='*.h' --include='*.cc' --include='*.md' --include='*.sh' --include='*.txt' --exclude=architecture_test.sh; then
  echo "citation: the repository explains itself (docs/model.md, docs/data.md)"
  fail=1
fi

while IFS= read -r name; do
  files=$(grep -rlF "\"$name\"" "${sources[@]}" --include='*.h' --include='*.cc' | sort)
  count=$(grep -c . <<<"$files" || true)
  if ((count > 2)); then
    echo "method name \"$name\" is spelled in $count files:" $files
    fail=1
  fi
done < <(grep -rhoE 'kMethodName = "[^"]+"|kRefitMethodName = "[^"]+"|kNominalMethodName = "[^"]+"' methods |
           sed -E 's/.*"([^"]+)"/\1/' | sort -u)

readers='\.(Integer|Number|Text|List|Flag|Has|Given|OptionalInteger|OptionalNumber)\("'
while IFS= read -r key; do
  if ! grep -rqE "${readers}${key}\"" methods --include='*.h' --include='*.cc'; then
    echo "option \"$key\" is declared but no method reads it (methods/method_options.h)"
    fail=1
  fi
done < <(grep -rhoE '(Integer|Number|Choice|List|Flag|Text)Option\(\s*"[a-z_0-9]+"' methods |
           sed -E 's/.*"([^"]+)"/\1/' | sort -u)

if grep -rnP '^(?!\s*//).*\bmodel(\.(at|value|contains|find)\("|\["[a-z_]+"\](?!(\["[^"]*"\])*\s*=[^=])(?!\.push_back))' \
     "${sources[@]}" --include='*.h' --include='*.cc' | grep -v '^core/model_view\.'; then
  echo "model key: read it through ModelView (core/model_view.h)"
  fail=1
fi

if command -v ctags >/dev/null && ctags --version | grep -q 'Universal Ctags'; then
  while IFS=$'\t' read -r file line end name; do
    # The body opens on the first line from the signature's that ends with '{'.
    open=$(awk -v from="$line" -v to="$end" 'NR >= from && NR <= to && /\{[[:space:]]*$/ { print NR; exit }' "$file")
    body=$((end - ${open:-$line} - 1))
    if ((body > 80)); then
      echo "function: $name ($file:$line) has a body of $body lines; at most 80"
      fail=1
    fi
  done < <(ctags -R --languages=C++ --langmap=C++:+.in --c++-kinds=f --fields=+ne -o - "${layers[@]}" |
             awk -F'\t' '{ l = ""; e = ""
                           for (i = 4; i <= NF; i++) { if ($i ~ /^line:/) l = substr($i, 6)
                                                      if ($i ~ /^end:/) e = substr($i, 5) }
                           if (l != "" && e != "" && e - l > 81) print $2 "\t" l "\t" e "\t" $1 }')
else
  echo "function length: not checked (Universal Ctags not installed: tools/install-deps.sh --test)"
fi

exit $fail
