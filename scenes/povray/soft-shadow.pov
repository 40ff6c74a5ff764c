// The soft-shadow comparison scene of docs/ACCURACY.md ("Against POV-Ray"): a ground plane, a sphere of radius 0.5
// at height 1 and a disk light of radius 0.25 at height 3, one camera ray per pixel. scenes/povray/soft-shadow.json
// is the same scene for this library (z up there, y up here). Declared values are set from the command line:
// +DN=<lights per side> +DA=<adaptive level> (-1: not adaptive) +DJ=<1 jitter, 0 none>.
#version 3.7;
#ifndef (N) #declare N = 9; #end
#ifndef (A) #declare A = 1; #end
#ifndef (J) #declare J = 1; #end
global_settings { assumed_gamma 1.0 max_trace_level 1 }
camera { location <0, 2.6, -4.2> look_at <0, 0.6, 0> angle 40 right x*image_width/image_height }
light_source {
  <0.6, 3, 0.4> color rgb 1
  area_light <0.5, 0, 0>, <0, 0, 0.5>, N, N
  #if (A >= 0) adaptive A #end
  #if (J) jitter #end
  circular orient
}
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 1, 0>, 0.5 pigment { color rgb <0.9, 0.5, 0.3> } finish { ambient 0.1 diffuse 0.7 } }
