#!/usr/bin/env bash
# Checks that every concept, formula and algorithm line of the original course slides
# (/work/shared/seed, "Advanced Game Physics -- Stoffsimulation") appears on a projected slide, in
# both editions: the text slides/edition_text.sh keeps of the decks for the language (speaker notes
# left out) and preamble.tex. A list line is WHAT|NEEDLE (both editions) or WHAT|EN NEEDLE|DE NEEDLE.
#   bash slides/check_seed.sh        (exit 1 and the missing items when something is missing)
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
list=$(cat <<'LIST'

# slide 2-3: introduction
three parts: MSS|Masse-Feder-Systeme
three parts: MFN|Masse-Feder-Netzwerke
three parts: PBD|Position-Based-Dynamics
MSS abbreviation|mass spring system, MSS
most cloth simulations go back to MSS|Most cloth simulations go back to mass-spring systems|Die meisten Stoffsimulationen gehen auf Masse-Feder-Systeme zurück
other fields: parameterisation|parameterisation|Parameterisierung
slide 4: history|Entwicklung Stoffsimulation
Waters87|[Waters87]
Provot96|[Provot96]
Mueller07|[Müller07]
Tyson13|[Tyson13]
# slides 5-7: mass-spring system
structure|Aufbau
particles of mass m|Massepartikel
stiffness k|Federhärte
rest length l0|Ruhelänge
spring force|spring force $\vec{F}_s$|Federkraft $\vec{F}_s$
force opposes the deformation|opposes the force that caused the deformation|wirkt der Kraft entgegen, die die Deformation verursacht hat
Hooke's law|Gesetz von Hooke
linear in the deformation|**linear** in the deformation|**linear** in der Deformation
acts along the spring|acts **along the spring**|wirkt **in Richtung der Feder**
Hooke formula|\vec{F}_s = - \frac{\vb{p}_1 - \vb{p}_0}{\|\vb{p}_1 - \vb{p}_0\|}\; k \cdot \Delta l
ODE|Differenzialgleichung
v = x dot|v(t) = \dot{x}(t)
a = x ddot|a(t) = \ddot{x}(t)
# slides 8-11: mass-spring networks
MFN structure|Aufbau eines MFN
MFN dynamics|Dynamik eines deformierten MFN
MFN simulation|Simulation (\de{Simulation})|Simulation eines MFN
integration error|Fehler der Integration
solved explicitly|die DGL wird explizit gelöst
error depends on dt|the error depends on the time step $\Delta t$|der Fehler hängt vom Zeitschritt $\Delta t$ ab
unstable for large steps|unstable for large time steps|instabil für hohe Zeitschritte
super-elasticity|Superelastizität
rubber-like|rubber-like|gummiartigen Resultaten
stiffness not unbounded|cannot be raised without limit|nicht unbegrenzt erhöhen
T0|T_0 \approx \pi\sqrt{\frac{m}{k}}
k_krit (corrected)|k_{krit} \approx m\,\frac{\pi^2}{\Delta t^2}
the slide's slip named|upside down|auf dem Kopf
# slides 12-13: cloth with MFN
data structure|Datenstruktur
grid|auf einem Gitter angeordnete Massepartikel
total mass|m_{gesamt} = \sum_i m_i
springs restrict the motion|Federn, durch welche die Stoffbewegung beschränkt wird
structural springs|Strukturfedern
shear springs|Scherfedern
bending springs|Biegefedern
sequence|Ablauf
# slides 14-16: PBD
problems with MFN|Probleme mit MFN
not robust for large steps|stark unrobust
stiffness bounded|Federhärten begrenzt
natural period|Eigenperiode
approach|Ansatz
solve directly for positions|**directly for the positions**|**direkt für die Positionen**
position x_i|$\vb{x}_i$
predicted position|geschätzte Position
inverse mass|inverse Masse
velocity v_i|$\vb{v}_i$
constraint = Bedingung|Bedingung
cardinality|Kardinalität
cost function|C_j : \mathbb{R}^{3 n_j} \rightarrow \mathbb{R}
weight (stiffness)|Gewicht
equality|Gleichung
inequality|Ungleichung
minimise the costs|minimise the costs|die Kosten minimieren
# slides 17-21: the algorithm, lines (1)-(17), and its four phases
line 1|\pbdl{1}{0}{0}{\textbf{forall} vertices $i$}
line 2|initialize $\vb{x}_i = \vb{x}_i^0,\ \vb{v}_i = \vb{v}_i^0,\ w_i = 1/m_i$
line 3|\pbdl{3}{0}{0}{\textbf{endfor}}
line 4|\pbdl{4}{0}{0}{\textbf{loop}}
line 5|$\vb{v}_i \leftarrow \vb{v}_i + \Delta t\, w_i\, \vb{f}_{ext}(\vb{x}_i)$
line 6|dampVelocities$(\vb{v}_1, \dots, \vb{v}_N)$
line 7|$\vb{p}_i \leftarrow \vb{x}_i + \Delta t\, \vb{v}_i$
line 8|generateCollisionConstraints$(\vb{x}_i \rightarrow \vb{p}_i)$
line 9|\textbf{loop} solverIterations \textbf{times}
line 10|projectConstraints$(C_1, \dots, C_{M+M_{coll}}, \vb{p}_1, \dots, \vb{p}_N)$
line 11|\pbdl{11}{3}{1}{\textbf{endloop}}
line 12|\pbdl{12}{4}{1}{\textbf{forall} vertices $i$}
line 13|$\vb{v}_i \leftarrow (\vb{p}_i - \vb{x}_i)/\Delta t$
line 14|$\vb{x}_i \leftarrow \vb{p}_i$
line 15|\pbdl{15}{4}{1}{\textbf{endfor}}
line 16|velocityUpdate$(\vb{v}_1, \dots, \vb{v}_N)$
line 17|\pbdl{17}{0}{0}{\textbf{endloop}}
algorithm slide|\pbdalgorithm{0}
phase 1 slide|\pbdalgorithm{1}
phase 2 slide|\pbdalgorithm{2}
phase 3 slide|\pbdalgorithm{3}
phase 4 slide|\pbdalgorithm{4}
phase 1 name|Geschwindigkeiten integrieren
phase 2 name|Positionen schätzen
phase 3 name|Positionsschätzungen aktualisieren $\rightarrow$ Constraints lösen
phase 4 name|Geschwindigkeits-Update und Positionen setzen
# slide 22: distance constraint
distance constraint|Distanz-Constraint
models a spring, linear costs|"linear costs"|"lineare Kosten"
C distance|C(\vb{p}_1, \vb{p}_2) = |\vb{p}_1 - \vb{p}_2| - d
projection|Projektion des Constraint
dp1|\Delta\vb{p}_1 = -\frac{w_1}{w_1 + w_2}\,\bigl(|\vb{p}_1 - \vb{p}_2| - d\bigr)\,\frac{\vb{p}_1 - \vb{p}_2}{|\vb{p}_1 - \vb{p}_2|}
dp2|\Delta\vb{p}_2 = +\frac{w_2}{w_1 + w_2}\,\bigl(|\vb{p}_1 - \vb{p}_2| - d\bigr)\,\frac{\vb{p}_1 - \vb{p}_2}{|\vb{p}_1 - \vb{p}_2|}
# slide 23: bending constraint
bending constraint|Biege-Constraint
stiffness of the material|Festigkeit des Materials
C bending|C(\vb{p}_1, \vb{p}_2, \vb{p}_3, \vb{p}_4) = \arccos(\vb{n}_1 \cdot \vb{n}_2) - \varphi_0
appendix A|appendix A
q3|\vb{q}_3 = \frac{\vb{p}_2 \times \vb{n}_2 + (\vb{n}_1 \times \vb{p}_2)\,d}{|\vb{p}_2 \times \vb{p}_3|}
q4|\vb{q}_4 = \frac{\vb{p}_2 \times \vb{n}_1 + (\vb{n}_2 \times \vb{p}_2)\,d}{|\vb{p}_2 \times \vb{p}_4|}
q2|\vb{q}_2 = -\frac{\vb{p}_3 \times \vb{n}_2 + (\vb{n}_1 \times \vb{p}_3)\,d}{|\vb{p}_2 \times \vb{p}_3|}
q2 second term|-\frac{\vb{p}_4 \times \vb{n}_1 + (\vb{n}_2 \times \vb{p}_4)\,d}{|\vb{p}_2 \times \vb{p}_4|}
q1|\vb{q}_1 = -\vb{q}_2 - \vb{q}_3 - \vb{q}_4
dp_i bending|\Delta\vb{p}_i = -\frac{w_i \sqrt{1 - d^2}\,\bigl(\arccos(d) - \varphi_0\bigr)}{\sum_j w_j |\vb{q}_j|^2}\,\vb{q}_i
# slide 24: collision constraint
collision constraint|Kollisions-Constraint
C collision (corrected sign of h)|C(\vb{p}) = (\vb{p} - \vb{q}_s) \cdot \vb{n}_s - h
the slide's + h named|the original slide prints "$+\,h$"|Die Originalfolie druckt "$+\,h$"
projection: earlier lectures|Kollisionsantwort
velocity treated separately|die Geschwindigkeit muss gesondert beachtet werden
LIST
)
status=0
for lang in en de; do
  text=$(bash "$SRC/edition_text.sh" "$lang" --projected "$SRC"/[0-9][0-9]_*.md; cat "$SRC/preamble.tex")
  missing=0 n=0
  while IFS='|' read -r what en de; do
    [[ -z $what || $what == \#* ]] && continue
    n=$((n + 1))
    needle=$en
    [[ $lang == de && -n $de ]] && needle=$de
    grep -qF -- "$needle" <<<"$text" || { echo "missing ($lang): $what  ($needle)"; missing=$((missing + 1)); }
  done <<<"$list"
  echo "seed coverage ($lang): $((n - missing)) of $n items found on the slides"
  ((missing == 0)) || status=1
done
exit $status
