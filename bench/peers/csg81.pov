// 81 CSG objects: bench/peers/csg81.scene for POV-Ray 3.7.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/512 ambient_light rgb 0.12 }
background { rgb 0 }
camera { location <22, -30, 20> sky <0, 0, 1> up <0, 0, 1> right <-4/3, 0, 0>
         angle 2 * degrees(atan(tan(radians(20)) * 4 / 3)) look_at <0, 0, -1> }
light_source { <60, -50, 90> color rgb 0.9 }
light_source { <-70, -30, 50> color rgb 0.4 }
#include "csg.inc"
#declare I = -12;
#while (I <= 12)
  #declare J = -12;
  #while (J <= 12)
    object { Part translate <I, J, 0> }
    #declare J = J + 3;
  #end
  #declare I = I + 3;
#end
object { Floor }
