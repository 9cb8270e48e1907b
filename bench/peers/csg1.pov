// One CSG object: bench/peers/csg1.scene for POV-Ray 3.7 (camera as in
// sphere.pov: horizontal angle 2 atan(tan(15 deg) 4/3), right-handed z up).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/512 ambient_light rgb 0.12 }
background { rgb 0 }
camera { location <4.5, -6, 4> sky <0, 0, 1> up <0, 0, 1> right <-4/3, 0, 0>
         angle 2 * degrees(atan(tan(radians(15)) * 4 / 3)) look_at <0, 0, 0> }
light_source { <6, -5, 9> color rgb 0.9 }
light_source { <-7, -3, 5> color rgb 0.4 }
#include "csg.inc"
object { Part }
object { Floor }
