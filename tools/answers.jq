# answers.json for tools/report.sh (./lab report NN), in any of its formats:
#   {"predict": {FIELD: {"value": N, "what": "..."}}, "measure": {FIELD: {"value": N, "how": "..."}}, "explain": "..."}
#   {FIELD: {"predict": "...", "predicted": N, "measure": "...", "measured": N, "explanation": "..."}}
#   {FIELD: {"value": N, "how": "..."}}
# An entry whose members are all objects is a section of fields (predict, measure); any other object is a
# field; text or a number at the top is shown as a paragraph (explain). Every key a field has is shown.
def nums: ["value", "predicted", "measured"];
def texts: ["how", "what", "predict", "measure", "explanation"];
def is_section: type == "object" and length > 0 and all(.[]; type == "object");
# every field object, wherever it is
def fields: to_entries[] | .value | if is_section then .[] elif type == "object" then . else empty end;
def field_problems($p):
  to_entries[]
  | if (.key | IN(nums[])) and (.value | type | IN("number", "null") | not) then "\($p).\(.key): expected a number or null, got \(.value | tojson)"
    elif (.key | IN(texts[])) and (.value | type | IN("string", "null") | not) then "\($p).\(.key): expected text or null, got \(.value | tojson)"
    else empty end;
# the first line: "FIELD.KEY: what is wrong" (empty when the file is well formed)
def problems:
  if type != "object" then "(file): expected an object, got \(type)"
  else to_entries[] | .key as $k | .value
    | if is_section then to_entries[] | .key as $f | .value | field_problems("\($k).\($f)")
      elif type == "object" then field_problems($k)
      elif type == "array" then "\($k): expected an object, text or a number, got an array"
      else empty end
  end;
def colname: {"predict": "question (predict)", "predicted": "predicted", "measure": "command (measure)", "measured": "measured",
              "explanation": "explanation", "value": "value", "what": "what to predict", "how": "how it is measured"}[.] // .;
def cell: if . == null then "<td class=\"missing\">not entered</td>" elif type == "number" then "<td class=\"num\">\(.)</td>"
          elif type == "string" then "<td>\(@html)</td>" else "<td><code>\(tojson | @html)</code></td>" end;
# a table of fields (an object FIELD -> {key: value}), one column per key any of them has
def table:
  ([.[] | keys_unsorted[]] | unique) as $all
  | (["predict", "predicted", "measure", "measured", "explanation", "value", "what", "how"] | map(select(IN($all[])))) as $known
  | ($known + ($all - $known)) as $cols
  | "<table>\n<tr><th>field</th>" + ($cols | map("<th>\(colname | @html)</th>") | join("")) + "</tr>\n"
    + (to_entries | map(.value as $v | "<tr><th><code>\(.key | @html)</code></th>" + ($cols | map($v[.] | cell) | join("")) + "</tr>\n") | join(""))
    + "</table>";
def heading: {"predict": "Predict (from theory, before running)", "measure": "Measure (your code, the command in how)",
              "explain": "Explain (why the measurement differs from the prediction, or agrees)"}[.] // .;
def html:
  if length == 0 then "<p class=\"missing\">answers.json has no fields.</p>" else
    (with_entries(select(.value | type == "object" and (is_section | not)))) as $flat
    | (if ($flat | length) > 0 then $flat | table else empty end),
      (to_entries[] | select(.value | is_section) | "<h3>\(.key | heading | @html)</h3>\n" + (.value | table)),
      (to_entries[] | select(.value | type | IN("string", "number", "null"))
       | "<h3>\(.key | heading | @html)</h3>\n"
         + (if .value == null or .value == "" then "<p class=\"missing\">not written</p>" else "<p>\(.value | tostring | @html)</p>" end))
  end;
