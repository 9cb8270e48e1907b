// Sphere on a plane: bench/peers/sphere.scene for POV-Ray 3.7.
// maprt's camera: FOV is the vertical angle, z up, right-handed; POV-Ray's
// angle is horizontal, so angle = 2 atan(tan(20 deg) * 4/3) = 51.75 deg,
// and right = -4/3 x makes the frame right-handed.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/512 ambient_light rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
camera { location <0, -8, 3> sky <0, 0, 1> up <0, 0, 1> right <-4/3, 0, 0>
         angle 2 * degrees(atan(tan(radians(20)) * 4 / 3)) look_at <0, 0, 0.8> }
light_source { <5, -6, 10> color rgb 0.9 }
sphere { <0, 0, 1>, 1
  pigment { rgb <0.8, 0.2, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 } }
plane { z, 0
  pigment { rgb <0.6, 0.6, 0.55> }
  finish { ambient 0.1 diffuse 0.8 } }
