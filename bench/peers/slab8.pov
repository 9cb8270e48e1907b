// A slab minus 8 cylinders: bench/slab-8.scene (640x480) for POV-Ray 3.7.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/512 ambient_light rgb 0.1 }
background { rgb 0 }
camera { location <0, -14, 18> sky <0, 0, 1> up <0, 0, 1> right <-4/3, 0, 0>
         angle 2 * degrees(atan(tan(radians(20)) * 4 / 3)) look_at <0, 0, 0> }
light_source { <6, -8, 20> color rgb 1 }
#declare Hole = texture { pigment { rgb <0.8, 0.6, 0.3> } finish { ambient 1 diffuse 0.8 } }
difference {
  box { <-8, -8, 0>, <8, 8, 1>
        texture { pigment { rgb <0.7, 0.7, 0.75> } finish { ambient 1 diffuse 0.8 phong 0.2 phong_size 20 } } }
  #declare I = 0;
  #while (I < 8)
    cylinder { <0, 0, -0.5>, <0, 0, 1.5>, 0.15 texture { Hole }
               translate <-4.6667 + 4.6667 * mod(I, 3), -4.6667 + 4.6667 * div(I, 3), 0> }
    #declare I = I + 1;
  #end
}
