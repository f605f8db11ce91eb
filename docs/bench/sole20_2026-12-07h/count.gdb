set pagination off
set breakpoint pending on
break robot_strain_shape.c:217
break robot_strain_shape.c:221
ignore 1 100000000
ignore 2 100000000
run
info breakpoints
