# fig1-single.awk — writes scenes/fig1-single.scene: the Figure 1 object of
# scenes/fig1.scene built from single-attribute primitives only (every tile,
# the band, the mirror panel, each letter stroke and each disc its own
# primitive, joined by CSG), for the multi- against single-attribute
# comparison in docs/pds.md. Run:
#   awk -f tools/fig1-single.awk > scenes/fig1-single.scene &&
#   sh scenes/cardseq.sh FG1S scenes/fig1-single.scene
#
# Geometry, in the can's object frame (u = angle / 2 pi, v = z / 1.6 on the
# side; x = 2u - 1, y = 2v - 1 on the top):
# - the CPG operand order (logo over panel over band over tiles) becomes
#   stacked shells: grout can r = 1, tiles 1.0005, band 1.0010, panel
#   1.0015, letters 1.0020 (1/2000 of the radius, under a pixel at 1024);
# - a region u0..u1 x v0..v1 of the side is the shell's cylinder
#   intersected with a block whose sides meet the shell at the angles
#   2 pi u0 and 2 pi u1 and whose height is 1.6 (v1 - v0);
# - an ellipse of the side is an elliptic cylinder along the radius through
#   its centre, semi-axes R sin(2 pi ru) across and 1.6 rv up (its widest
#   points exact, within 1% of the angle in between);
# - the discs of the top are short cylinders 0.0002-0.0004 above it; the
#   blue one is a disc of the can's own radius cut by its circle, so that
#   its dimples keep the can top's (u,v).
function deg(a) { return a * 180 / PI }
# Prints one statement as cards of at most 72 columns (73-80 are the
# sequence field), continued with " -".
function emit(st,    n, t, k, line) {
    if (substr(st, 1, 1) == "*") {
        print st
        return
    }
    n = split(st, t, " ")
    line = t[1]
    for (k = 2; k <= n; k++) {
        if (length(line) + 1 + length(t[k]) > 69) {
            print line " -"
            line = "   "
        }
        line = line " " t[k]
    }
    print line
}
# A block sector: region u0..u1 x v0..v1 on radius r.
function sector(name, r, u0, u1, v0, v1,    h, tc, w, x0) {
    h = (u1 - u0) * PI
    tc = deg((u0 + u1) * PI)
    w = r * sin(h)
    x0 = r * cos(h) - 0.05
    if (x0 > 0.9) x0 = 0.9
    emit(sprintf("BLOCK %s %.7f %.7f %.7f TRANSLATE %.7f %.7f %.7f ROTATE Z %.7f", \
        name, r + 0.1 - x0, 2 * w, 1.6 * (v1 - v0), x0, -w, 1.6 * v0, tc))
}
# An elliptic cylinder along the radius through side point (uc, vc).
function ellipse(name, r, uc, vc, ru, rv,    t, rs, rz, c, s) {
    t = 2 * PI * uc
    rs = r * sin(2 * PI * ru)
    rz = 1.6 * rv
    c = cos(t); s = sin(t)
    emit(sprintf("CYLINDER %s 1 1 MATRIX 0 %.7f %.7f %.7f  0 %.7f %.7f %.7f  %.7f 0 0 %.7f", \
        name, -rs * s, 0.7 * c, 0.5 * c, rs * c, 0.7 * s, 0.5 * s, -rz, 1.6 * vc))
}
# Letter L of the logo: an elliptic ring at logo x = cx (outer radii 0.21
# 0.40, inner 0.12 0.25, centre y 0.5) minus the opening x0..x1 x y0..y1.
function letter(l, cx, x0, x1, y0, y1) {
    emit(sprintf("CYLINDER %sSHELL %.4f 1.6 ATTR LETTER", l, RL))
    ellipse(l "O", RL, lu(cx), lv(0.50), 0.22 * 0.21, 0.46 * 0.40)
    ellipse(l "I", RL, lu(cx), lv(0.50), 0.22 * 0.12, 0.46 * 0.25)
    sector(l "CUT", RL, lu(x0), lu(x1), lv(y0), lv(y1))
    emit(sprintf("INTER %sDISC %sSHELL %sO ATTR LETTER", l, l, l))
    emit(sprintf("DIFF LET%s %sDISC %sI ATTR LETTER %sCUT ATTR LETTER", l, l, l, l))
}
# The logo's unit square on the side: u = 0.39 + 0.22 x, v = 0.37 + 0.46 y.
function lu(x) { return 0.39 + 0.22 * x }
function lv(y) { return 0.37 + 0.46 * y }
BEGIN {
    PI = atan2(0, -1)
    RT = 1.0005; RB = 1.0010; RP = 1.0015; RL = 1.0020
    emit("* FIG1-SINGLE SCENE: the Figure 1 object of fig1.scene from single-")
    emit("* attribute primitives only, joined by CSG (written by")
    emit("* tools/fig1-single.awk; docs/pds.md compares the two). Camera, lights,")
    emit("* attributes, floor, balls and block are those of fig1.scene.")
    emit("EYE        5.5  -7.0   4.0")
    emit("LOOKAT     0.0   0.0   0.75")
    emit("UP         0     0     1")
    emit("FOV        27")
    emit("SIZE       1024 1024")
    emit("AMBIENT    0.20 0.20 0.20")
    emit("BACKGROUND 0.05 0.06 0.16")
    emit("DEPTH      5")
    emit("LIGHT  8.0 -6.0 10.0  COLOR 1 1 1  INTENSITY 0.85")
    emit("LIGHT -7.0 -5.0  7.0  COLOR 1 0.95 0.85  INTENSITY 0.45")
    emit("BUMP RIBS    WAVES    AMPLITUDE 0.012  FREQUENCY 90 0")
    emit("BUMP DIMPLE  DIMPLES  AMPLITUDE 0.06   FREQUENCY 7 7")
    emit("ATTR CAN     COLOR 0.85 0.82 0.72  DIFFUSE 0.75  SPECULAR 0.3 EXPONENT 30")
    emit("ATTR SILVER  COLOR 0.90 0.90 0.92  DIFFUSE 0.05 SPECULAR 0.9 EXPONENT 200  MIRROR 0.85")
    emit("ATTR LETTER  COLOR 0.10 0.15 0.55  DIFFUSE 0.8  SPECULAR 0.5 EXPONENT 60")
    emit("ATTR BAND    COLOR 0.80 0.62 0.22  DIFFUSE 0.7  SPECULAR 0.6 EXPONENT 40  BUMP RIBS")
    emit("ATTR TILE1   COLOR 0.78 0.30 0.22  DIFFUSE 0.8  SPECULAR 0.2")
    emit("ATTR TILE2   COLOR 0.90 0.86 0.78  DIFFUSE 0.8  SPECULAR 0.2")
    emit("ATTR TILE3   COLOR 0.28 0.45 0.62  DIFFUSE 0.8  SPECULAR 0.2")
    emit("ATTR GROUT   COLOR 0.30 0.30 0.30  DIFFUSE 0.9")
    emit("ATTR DOTRED  COLOR 0.85 0.15 0.12  DIFFUSE 0.8  SPECULAR 0.4")
    emit("ATTR DOTGOLD COLOR 0.95 0.75 0.30  DIFFUSE 0.2  SPECULAR 0.8 EXPONENT 120  MIRROR 0.6")
    emit("ATTR DOTBLUE COLOR 0.20 0.35 0.85  DIFFUSE 0.8  SPECULAR 0.5 EXPONENT 50  BUMP DIMPLE")
    emit("ATTR FLOOR1  COLOR 0.62 0.62 0.58  DIFFUSE 0.8")
    emit("ATTR FLOOR2  COLOR 0.30 0.32 0.36  DIFFUSE 0.8  MIRROR 0.15")
    emit("ATTR CHROME  COLOR 0.90 0.90 0.90  DIFFUSE 0.1  SPECULAR 0.8 EXPONENT 80  MIRROR 0.75")
    emit("ATTR YELLOW  COLOR 0.90 0.75 0.15  DIFFUSE 0.8  SPECULAR 0.3")
    emit("ATTR GREEN   COLOR 0.22 0.58 0.38  DIFFUSE 0.8  SPECULAR 0.5 EXPONENT 40")
    emit("PDS CHECKER TILING SQUARE 0.5 CYCLE 1 1 0")
    emit("TILES FLOOR1 FLOOR2")
    emit("END")
    emit("* The can: grout on the side, CAN on the top.")
    emit("CYLINDER GROUTCAN 1 1.6 ATTR GROUT")
    emit("CYLINDER CANTOP 0.9995 0.0102 ATTR CAN TRANSLATE 0 0 1.59")
    emit("* Tiles: 24 around, 6 up, mortar 0.004 wide (fig1.scene's SIDETILE).")
    w = 0.0416667; hh = 0.1666667; m = 0.002
    ops = ""
    for (j = 0; j < 6; j++)
        for (i = 0; i < 24; i++) {
            emit(sprintf("CYLINDER TC%d_%d %.4f 1.6 ATTR TILE%d", i, j, RT, (i + j) % 3 + 1))
            sector(sprintf("TB%d_%d", i, j), RT, i * w + m, (i + 1) * w - m, j * hh + m, (j + 1) * hh - m)
            emit(sprintf("INTER T%d_%d TC%d_%d TB%d_%d ATTR TILE%d", i, j, i, j, i, j, (i + j) % 3 + 1))
            ops = ops " T" i "_" j
        }
    emit("* The band (v 0.10..0.24) all round.")
    emit(sprintf("CYLINDER RIBBAND %.4f 0.224 ATTR BAND TRANSLATE 0 0 0.16", RB))
    emit("* The mirror panel (u 0.37..0.63, v 0.33..0.87).")
    emit(sprintf("CYLINDER PANELC %.4f 1.6 ATTR SILVER", RP))
    sector("PANELB", RP, 0.37, 0.63, 0.33, 0.87)
    emit("INTER PANEL PANELC PANELB ATTR SILVER")
    emit("* The letters: C = outer ellipse - inner ellipse - opening, G the same")
    emit("* with its own opening, plus the bar.")
    letter("C", 0.26, 0.34, 0.50, 0.36, 0.64)
    letter("G", 0.74, 0.82, 1.00, 0.52, 0.72)
    emit(sprintf("CYLINDER BSHELL %.4f 1.6 ATTR LETTER", RL))
    sector("GBARB", RL, lu(0.75), lu(0.95), lv(0.42), lv(0.52))
    emit("INTER GBAR BSHELL GBARB ATTR LETTER")
    emit("* The three discs of the top (fig1.scene's TOPMAP).")
    emit("CYLINDER DOT1 0.34 0.0104 ATTR DOTRED TRANSLATE 0 0.44 1.59")
    emit("CYLINDER DOT2 0.34 0.0104 ATTR DOTGOLD TRANSLATE -0.38 -0.22 1.59")
    emit("CYLINDER DOT3TOP 1 0.0104 ATTR DOTBLUE TRANSLATE 0 0 1.59")
    emit("CYLINDER DOT3CUT 0.34 0.02 ATTR DOTBLUE TRANSLATE 0.38 -0.22 1.585")
    emit("INTER DOT3 DOT3TOP DOT3CUT ATTR DOTBLUE")
    emit("UNION FIG1 GROUTCAN CANTOP RIBBAND PANEL LETC LETG GBAR DOT1 DOT2 DOT3" ops)
    emit("SPHERE   BALL1  0.6       ATTR CHROME  TRANSLATE 1.9 -0.9 0.6")
    emit("BLOCK    BOX1   0.9 0.9 0.9  ATTR YELLOW  ROTATE Z 20 TRANSLATE -2.4 0.2 0")
    emit("SPHERE   BALL2  1.3       ATTR GREEN  TRANSLATE -0.7 2.5 1.3")
    emit("HALFSPACE GROUND          ATTR FLOOR1")
    emit("FACE GROUND PLANE CHECKER")
    emit("* The cylinder turned as in fig1.scene.")
    emit("OBJECT FIG1 ROTATE Z 128")
    emit("OBJECT BALL1")
    emit("OBJECT BOX1")
    emit("OBJECT BALL2")
    emit("OBJECT GROUND")
}
