# A points file as the student copy holds it (./lab release; tests/docs/docs_links_check.sh reads
# the README's example grade through it): the experiments' numbers are graded by the instructor
# (tests/instructor/experiments/), so of the Experiments.* tests only AnswerFileIsComplete stays, and
# "graded_apart" records the points the copy's ./lab grade leaves out (it prints them under its table).
# The copy's own points file passes through unchanged.
(.tests | to_entries | map(select((.key | startswith("Experiments.")) and .key != "Experiments.AnswerFileIsComplete"))
        | map(.value) | add // 0) as $apart
| .tests |= with_entries(select((.key | startswith("Experiments.") | not) or .key == "Experiments.AnswerFileIsComplete"))
| if $apart > 0 then .graded_apart = {"experiments": $apart} else . end
