module top(clock,start,reset,load_enable,load_module,load_address,load_data,host_write,host_address,host_data,busy,n_s,n_beam,n_b,bs,ext_addr$0,ext_addr$1,ext_addr$2,ext_addr$3,ext_data$0,ext_data$1,ext_data$2,ext_data$3,px_valid$0,px_valid$1,px_valid$2,px_valid$3,px_x$0,px_x$1,px_x$2,px_x$3,px_y$0,px_y$1,px_y$2,px_y$3,px_face$0,px_face$1,px_face$2,px_face$3,res_beat$0,res_beat$1,res_beat$2,res_beat$3,res_valid$0,res_valid$1,res_valid$2,res_valid$3,res$0,res$1,res$2,res$3);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  reset;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [15:0] load_address;
    input wire  [15:0] load_data;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  busy;
    output reg  [15:0] n_s;
    output reg  [15:0] n_beam;
    output reg  [15:0] n_b;
    output reg  bs;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    output reg  [31:0] ext_addr$2;
    output reg  [31:0] ext_addr$3;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    input wire  [15:0] ext_data$2;
    input wire  [15:0] ext_data$3;
    output reg  px_valid$0;
    output reg  px_valid$1;
    output reg  px_valid$2;
    output reg  px_valid$3;
    output reg  [15:0] px_x$0;
    output reg  [15:0] px_x$1;
    output reg  [15:0] px_x$2;
    output reg  [15:0] px_x$3;
    output reg  [15:0] px_y$0;
    output reg  [15:0] px_y$1;
    output reg  [15:0] px_y$2;
    output reg  [15:0] px_y$3;
    output reg  [2:0] px_face$0;
    output reg  [2:0] px_face$1;
    output reg  [2:0] px_face$2;
    output reg  [2:0] px_face$3;
    output reg  res_beat$0;
    output reg  res_beat$1;
    output reg  res_beat$2;
    output reg  res_beat$3;
    output reg  res_valid$0;
    output reg  res_valid$1;
    output reg  res_valid$2;
    output reg  res_valid$3;
    output reg  [63:0] res$0;
    output reg  [63:0] res$1;
    output reg  [63:0] res$2;
    output reg  [63:0] res$3;
    
    // Constant declarations
    localparam  gradient = 1'b1;
    localparam  flush_clocks = 8'h1c;
    
    // Stub signals
    reg  view$clock;
    reg  view$host_write;
    reg  [23:0] view$host_address;
    reg  [63:0] view$host_data;
    wire  [63:0] view$q$0;
    wire  [63:0] view$q$1;
    wire  [63:0] view$q$2;
    wire  [63:0] view$q$3;
    wire  [63:0] view$q$4;
    wire  [63:0] view$q$5;
    wire  [63:0] view$q$6;
    wire  [63:0] view$q$7;
    wire  [63:0] view$q$8;
    wire  [63:0] view$q$9;
    wire  [63:0] view$q$10;
    reg  cfb$clock;
    reg  [63:0] cfb$dims;
    reg  [63:0] cfb$slices;
    reg  [63:0] cfb$axes;
    reg  [63:0] cfb$address_reg;
    reg  [63:0] cfb$dx;
    reg  [63:0] cfb$dy;
    reg  [63:0] cfb$eye_x;
    reg  [63:0] cfb$eye_y;
    reg  [63:0] cfb$eye_z;
    reg  [63:0] cfb$beats;
    reg  cfb$start;
    reg  cfb$reset;
    wire  cfb$busy;
    reg  cfb$load_enable;
    reg  [7:0] cfb$load_module;
    reg  [15:0] cfb$load_address;
    reg  [15:0] cfb$load_data;
    wire  cfb$valid;
    wire  [15:0] cfb$n_s;
    wire  [15:0] cfb$n_beam;
    wire  [15:0] cfb$n_b;
    wire  cfb$bs;
    wire  [15:0] cfb$value$0;
    wire  [15:0] cfb$value$1;
    wire  [15:0] cfb$value$2;
    wire  [15:0] cfb$value$3;
    wire  [15:0] cfb$x$0;
    wire  [15:0] cfb$x$1;
    wire  [15:0] cfb$x$2;
    wire  [15:0] cfb$x$3;
    wire  [15:0] cfb$y$0;
    wire  [15:0] cfb$y$1;
    wire  [15:0] cfb$y$2;
    wire  [15:0] cfb$y$3;
    wire  [15:0] cfb$z$0;
    wire  [15:0] cfb$z$1;
    wire  [15:0] cfb$z$2;
    wire  [15:0] cfb$z$3;
    wire  [31:0] cfb$address$0;
    wire  [31:0] cfb$address$1;
    wire  [31:0] cfb$address$2;
    wire  [31:0] cfb$address$3;
    wire  cfb$pad$0;
    wire  cfb$pad$1;
    wire  cfb$pad$2;
    wire  cfb$pad$3;
    wire  cfb$sr$0;
    wire  cfb$sr$1;
    wire  cfb$sr$2;
    wire  cfb$sr$3;
    wire  cfb$er$0;
    wire  cfb$er$1;
    wire  cfb$er$2;
    wire  cfb$er$3;
    wire  [15:0] cfb$base_x$0;
    wire  [15:0] cfb$base_x$1;
    wire  [15:0] cfb$base_x$2;
    wire  [15:0] cfb$base_x$3;
    wire  [15:0] cfb$base_y$0;
    wire  [15:0] cfb$base_y$1;
    wire  [15:0] cfb$base_y$2;
    wire  [15:0] cfb$base_y$3;
    wire  [2:0] cfb$face$0;
    wire  [2:0] cfb$face$1;
    wire  [2:0] cfb$face$2;
    wire  [2:0] cfb$face$3;
    wire  cfb$at_edge$0;
    wire  cfb$at_edge$1;
    wire  cfb$at_edge$2;
    wire  cfb$at_edge$3;
    wire  cfb$invalid$0;
    wire  cfb$invalid$1;
    wire  cfb$invalid$2;
    wire  cfb$invalid$3;
    wire  cfb$halo$0;
    wire  cfb$halo$1;
    wire  cfb$halo$2;
    wire  cfb$halo$3;
    wire  [31:0] cfb$ext_addr$0;
    wire  [31:0] cfb$ext_addr$1;
    wire  [31:0] cfb$ext_addr$2;
    wire  [31:0] cfb$ext_addr$3;
    reg  [15:0] cfb$ext_data$0;
    reg  [15:0] cfb$ext_data$1;
    reg  [15:0] cfb$ext_data$2;
    reg  [15:0] cfb$ext_data$3;
    wire  cfb$dx_neg$0;
    wire  cfb$dx_neg$1;
    wire  cfb$dx_neg$2;
    wire  cfb$dx_neg$3;
    wire  [15:0] cfb$dx_mag$0;
    wire  [15:0] cfb$dx_mag$1;
    wire  [15:0] cfb$dx_mag$2;
    wire  [15:0] cfb$dx_mag$3;
    wire  cfb$dy_neg$0;
    wire  cfb$dy_neg$1;
    wire  cfb$dy_neg$2;
    wire  cfb$dy_neg$3;
    wire  [15:0] cfb$dy_mag$0;
    wire  [15:0] cfb$dy_mag$1;
    wire  [15:0] cfb$dy_mag$2;
    wire  [15:0] cfb$dy_mag$3;
    reg  lanes$0$clock;
    reg  lanes$0$host_write;
    reg  [23:0] lanes$0$host_address;
    reg  [63:0] lanes$0$host_data;
    reg  [63:0] lanes$0$dims;
    reg  [63:0] lanes$0$beats;
    reg  [63:0] lanes$0$order;
    reg  lanes$0$beat_valid;
    reg  [15:0] lanes$0$value;
    reg  [15:0] lanes$0$x;
    reg  [15:0] lanes$0$y;
    reg  lanes$0$pad;
    reg  lanes$0$invalid;
    reg  lanes$0$halo;
    reg  lanes$0$sr;
    reg  lanes$0$er;
    reg  [15:0] lanes$0$base_x;
    reg  [15:0] lanes$0$base_y;
    reg  [2:0] lanes$0$face;
    reg  lanes$0$at_edge;
    reg  lanes$0$dx_neg;
    reg  [15:0] lanes$0$dx_mag;
    reg  lanes$0$dy_neg;
    reg  [15:0] lanes$0$dy_mag;
    reg  [15:0] lanes$0$g_from_left_xm;
    reg  [15:0] lanes$0$g_from_left_ym;
    reg  [15:0] lanes$0$g_from_left_zm;
    reg  [15:0] lanes$0$g_from_right_xp;
    reg  [15:0] lanes$0$g_from_right_yp;
    reg  [15:0] lanes$0$g_from_right_zp;
    wire  [15:0] lanes$0$g_to_right_xm;
    wire  [15:0] lanes$0$g_to_right_ym;
    wire  [15:0] lanes$0$g_to_right_zm;
    wire  [15:0] lanes$0$g_to_left_xp;
    wire  [15:0] lanes$0$g_to_left_yp;
    wire  [15:0] lanes$0$g_to_left_zp;
    wire  [63:0] lanes$0$t0s0;
    reg  [63:0] lanes$0$t0i1;
    wire  [63:0] lanes$0$t1s0;
    wire  [63:0] lanes$0$t1s1;
    reg  [63:0] lanes$0$t1i1;
    reg  [63:0] lanes$0$t1i2;
    wire  [63:0] lanes$0$t3s0;
    wire  [63:0] lanes$0$t3s1;
    reg  [63:0] lanes$0$t3i1;
    reg  [63:0] lanes$0$t3i2;
    wire  [63:0] lanes$0$t5s0;
    wire  [63:0] lanes$0$t5s1;
    wire  [63:0] lanes$0$t5s2;
    reg  [63:0] lanes$0$t5i1;
    reg  [63:0] lanes$0$t5i2;
    reg  [63:0] lanes$0$t5i3;
    wire  [63:0] lanes$0$t6s0;
    reg  [63:0] lanes$0$t6i1;
    wire  [63:0] lanes$0$t7s0;
    reg  [63:0] lanes$0$t7i1;
    wire  [63:0] lanes$0$t8s0;
    reg  [63:0] lanes$0$t8i1;
    reg  [63:0] lanes$0$t8il;
    wire  lanes$0$res_beat;
    wire  lanes$0$res_valid;
    wire  [63:0] lanes$0$res;
    wire  lanes$0$px_valid;
    wire  [15:0] lanes$0$px_x;
    wire  [15:0] lanes$0$px_y;
    wire  [2:0] lanes$0$px_face;
    reg  lanes$1$clock;
    reg  lanes$1$host_write;
    reg  [23:0] lanes$1$host_address;
    reg  [63:0] lanes$1$host_data;
    reg  [63:0] lanes$1$dims;
    reg  [63:0] lanes$1$beats;
    reg  [63:0] lanes$1$order;
    reg  lanes$1$beat_valid;
    reg  [15:0] lanes$1$value;
    reg  [15:0] lanes$1$x;
    reg  [15:0] lanes$1$y;
    reg  lanes$1$pad;
    reg  lanes$1$invalid;
    reg  lanes$1$halo;
    reg  lanes$1$sr;
    reg  lanes$1$er;
    reg  [15:0] lanes$1$base_x;
    reg  [15:0] lanes$1$base_y;
    reg  [2:0] lanes$1$face;
    reg  lanes$1$at_edge;
    reg  lanes$1$dx_neg;
    reg  [15:0] lanes$1$dx_mag;
    reg  lanes$1$dy_neg;
    reg  [15:0] lanes$1$dy_mag;
    reg  [15:0] lanes$1$g_from_left_xm;
    reg  [15:0] lanes$1$g_from_left_ym;
    reg  [15:0] lanes$1$g_from_left_zm;
    reg  [15:0] lanes$1$g_from_right_xp;
    reg  [15:0] lanes$1$g_from_right_yp;
    reg  [15:0] lanes$1$g_from_right_zp;
    wire  [15:0] lanes$1$g_to_right_xm;
    wire  [15:0] lanes$1$g_to_right_ym;
    wire  [15:0] lanes$1$g_to_right_zm;
    wire  [15:0] lanes$1$g_to_left_xp;
    wire  [15:0] lanes$1$g_to_left_yp;
    wire  [15:0] lanes$1$g_to_left_zp;
    wire  [63:0] lanes$1$t0s0;
    reg  [63:0] lanes$1$t0i1;
    wire  [63:0] lanes$1$t1s0;
    wire  [63:0] lanes$1$t1s1;
    reg  [63:0] lanes$1$t1i1;
    reg  [63:0] lanes$1$t1i2;
    wire  [63:0] lanes$1$t3s0;
    wire  [63:0] lanes$1$t3s1;
    reg  [63:0] lanes$1$t3i1;
    reg  [63:0] lanes$1$t3i2;
    wire  [63:0] lanes$1$t5s0;
    wire  [63:0] lanes$1$t5s1;
    wire  [63:0] lanes$1$t5s2;
    reg  [63:0] lanes$1$t5i1;
    reg  [63:0] lanes$1$t5i2;
    reg  [63:0] lanes$1$t5i3;
    wire  [63:0] lanes$1$t6s0;
    reg  [63:0] lanes$1$t6i1;
    wire  [63:0] lanes$1$t7s0;
    reg  [63:0] lanes$1$t7i1;
    wire  [63:0] lanes$1$t8s0;
    reg  [63:0] lanes$1$t8i1;
    reg  [63:0] lanes$1$t8il;
    wire  lanes$1$res_beat;
    wire  lanes$1$res_valid;
    wire  [63:0] lanes$1$res;
    wire  lanes$1$px_valid;
    wire  [15:0] lanes$1$px_x;
    wire  [15:0] lanes$1$px_y;
    wire  [2:0] lanes$1$px_face;
    reg  lanes$2$clock;
    reg  lanes$2$host_write;
    reg  [23:0] lanes$2$host_address;
    reg  [63:0] lanes$2$host_data;
    reg  [63:0] lanes$2$dims;
    reg  [63:0] lanes$2$beats;
    reg  [63:0] lanes$2$order;
    reg  lanes$2$beat_valid;
    reg  [15:0] lanes$2$value;
    reg  [15:0] lanes$2$x;
    reg  [15:0] lanes$2$y;
    reg  lanes$2$pad;
    reg  lanes$2$invalid;
    reg  lanes$2$halo;
    reg  lanes$2$sr;
    reg  lanes$2$er;
    reg  [15:0] lanes$2$base_x;
    reg  [15:0] lanes$2$base_y;
    reg  [2:0] lanes$2$face;
    reg  lanes$2$at_edge;
    reg  lanes$2$dx_neg;
    reg  [15:0] lanes$2$dx_mag;
    reg  lanes$2$dy_neg;
    reg  [15:0] lanes$2$dy_mag;
    reg  [15:0] lanes$2$g_from_left_xm;
    reg  [15:0] lanes$2$g_from_left_ym;
    reg  [15:0] lanes$2$g_from_left_zm;
    reg  [15:0] lanes$2$g_from_right_xp;
    reg  [15:0] lanes$2$g_from_right_yp;
    reg  [15:0] lanes$2$g_from_right_zp;
    wire  [15:0] lanes$2$g_to_right_xm;
    wire  [15:0] lanes$2$g_to_right_ym;
    wire  [15:0] lanes$2$g_to_right_zm;
    wire  [15:0] lanes$2$g_to_left_xp;
    wire  [15:0] lanes$2$g_to_left_yp;
    wire  [15:0] lanes$2$g_to_left_zp;
    wire  [63:0] lanes$2$t0s0;
    reg  [63:0] lanes$2$t0i1;
    wire  [63:0] lanes$2$t1s0;
    wire  [63:0] lanes$2$t1s1;
    reg  [63:0] lanes$2$t1i1;
    reg  [63:0] lanes$2$t1i2;
    wire  [63:0] lanes$2$t3s0;
    wire  [63:0] lanes$2$t3s1;
    reg  [63:0] lanes$2$t3i1;
    reg  [63:0] lanes$2$t3i2;
    wire  [63:0] lanes$2$t5s0;
    wire  [63:0] lanes$2$t5s1;
    wire  [63:0] lanes$2$t5s2;
    reg  [63:0] lanes$2$t5i1;
    reg  [63:0] lanes$2$t5i2;
    reg  [63:0] lanes$2$t5i3;
    wire  [63:0] lanes$2$t6s0;
    reg  [63:0] lanes$2$t6i1;
    wire  [63:0] lanes$2$t7s0;
    reg  [63:0] lanes$2$t7i1;
    wire  [63:0] lanes$2$t8s0;
    reg  [63:0] lanes$2$t8i1;
    reg  [63:0] lanes$2$t8il;
    wire  lanes$2$res_beat;
    wire  lanes$2$res_valid;
    wire  [63:0] lanes$2$res;
    wire  lanes$2$px_valid;
    wire  [15:0] lanes$2$px_x;
    wire  [15:0] lanes$2$px_y;
    wire  [2:0] lanes$2$px_face;
    reg  lanes$3$clock;
    reg  lanes$3$host_write;
    reg  [23:0] lanes$3$host_address;
    reg  [63:0] lanes$3$host_data;
    reg  [63:0] lanes$3$dims;
    reg  [63:0] lanes$3$beats;
    reg  [63:0] lanes$3$order;
    reg  lanes$3$beat_valid;
    reg  [15:0] lanes$3$value;
    reg  [15:0] lanes$3$x;
    reg  [15:0] lanes$3$y;
    reg  lanes$3$pad;
    reg  lanes$3$invalid;
    reg  lanes$3$halo;
    reg  lanes$3$sr;
    reg  lanes$3$er;
    reg  [15:0] lanes$3$base_x;
    reg  [15:0] lanes$3$base_y;
    reg  [2:0] lanes$3$face;
    reg  lanes$3$at_edge;
    reg  lanes$3$dx_neg;
    reg  [15:0] lanes$3$dx_mag;
    reg  lanes$3$dy_neg;
    reg  [15:0] lanes$3$dy_mag;
    reg  [15:0] lanes$3$g_from_left_xm;
    reg  [15:0] lanes$3$g_from_left_ym;
    reg  [15:0] lanes$3$g_from_left_zm;
    reg  [15:0] lanes$3$g_from_right_xp;
    reg  [15:0] lanes$3$g_from_right_yp;
    reg  [15:0] lanes$3$g_from_right_zp;
    wire  [15:0] lanes$3$g_to_right_xm;
    wire  [15:0] lanes$3$g_to_right_ym;
    wire  [15:0] lanes$3$g_to_right_zm;
    wire  [15:0] lanes$3$g_to_left_xp;
    wire  [15:0] lanes$3$g_to_left_yp;
    wire  [15:0] lanes$3$g_to_left_zp;
    wire  [63:0] lanes$3$t0s0;
    reg  [63:0] lanes$3$t0i1;
    wire  [63:0] lanes$3$t1s0;
    wire  [63:0] lanes$3$t1s1;
    reg  [63:0] lanes$3$t1i1;
    reg  [63:0] lanes$3$t1i2;
    wire  [63:0] lanes$3$t3s0;
    wire  [63:0] lanes$3$t3s1;
    reg  [63:0] lanes$3$t3i1;
    reg  [63:0] lanes$3$t3i2;
    wire  [63:0] lanes$3$t5s0;
    wire  [63:0] lanes$3$t5s1;
    wire  [63:0] lanes$3$t5s2;
    reg  [63:0] lanes$3$t5i1;
    reg  [63:0] lanes$3$t5i2;
    reg  [63:0] lanes$3$t5i3;
    wire  [63:0] lanes$3$t6s0;
    reg  [63:0] lanes$3$t6i1;
    wire  [63:0] lanes$3$t7s0;
    reg  [63:0] lanes$3$t7i1;
    wire  [63:0] lanes$3$t8s0;
    reg  [63:0] lanes$3$t8i1;
    reg  [63:0] lanes$3$t8il;
    wire  lanes$3$res_beat;
    wire  lanes$3$res_valid;
    wire  [63:0] lanes$3$res;
    wire  lanes$3$px_valid;
    wire  [15:0] lanes$3$px_x;
    wire  [15:0] lanes$3$px_y;
    wire  [2:0] lanes$3$px_face;
    reg  late$clock;
    reg  [63:0] late$dims;
    reg  [63:0] late$slices;
    reg  [63:0] late$axes;
    reg  [63:0] late$address_reg;
    reg  [63:0] late$dx;
    reg  [63:0] late$dy;
    reg  [63:0] late$eye_x;
    reg  [63:0] late$eye_y;
    reg  [63:0] late$eye_z;
    reg  [63:0] late$beats;
    reg  late$start;
    reg  late$reset;
    wire  late$busy;
    reg  late$load_enable;
    reg  [7:0] late$load_module;
    reg  [15:0] late$load_address;
    reg  [15:0] late$load_data;
    wire  late$valid;
    wire  [15:0] late$n_s;
    wire  [15:0] late$n_beam;
    wire  [15:0] late$n_b;
    wire  late$bs;
    wire  [15:0] late$value$0;
    wire  [15:0] late$value$1;
    wire  [15:0] late$value$2;
    wire  [15:0] late$value$3;
    wire  [15:0] late$x$0;
    wire  [15:0] late$x$1;
    wire  [15:0] late$x$2;
    wire  [15:0] late$x$3;
    wire  [15:0] late$y$0;
    wire  [15:0] late$y$1;
    wire  [15:0] late$y$2;
    wire  [15:0] late$y$3;
    wire  [15:0] late$z$0;
    wire  [15:0] late$z$1;
    wire  [15:0] late$z$2;
    wire  [15:0] late$z$3;
    wire  [31:0] late$address$0;
    wire  [31:0] late$address$1;
    wire  [31:0] late$address$2;
    wire  [31:0] late$address$3;
    wire  late$pad$0;
    wire  late$pad$1;
    wire  late$pad$2;
    wire  late$pad$3;
    wire  late$sr$0;
    wire  late$sr$1;
    wire  late$sr$2;
    wire  late$sr$3;
    wire  late$er$0;
    wire  late$er$1;
    wire  late$er$2;
    wire  late$er$3;
    wire  [15:0] late$base_x$0;
    wire  [15:0] late$base_x$1;
    wire  [15:0] late$base_x$2;
    wire  [15:0] late$base_x$3;
    wire  [15:0] late$base_y$0;
    wire  [15:0] late$base_y$1;
    wire  [15:0] late$base_y$2;
    wire  [15:0] late$base_y$3;
    wire  [2:0] late$face$0;
    wire  [2:0] late$face$1;
    wire  [2:0] late$face$2;
    wire  [2:0] late$face$3;
    wire  late$at_edge$0;
    wire  late$at_edge$1;
    wire  late$at_edge$2;
    wire  late$at_edge$3;
    wire  late$invalid$0;
    wire  late$invalid$1;
    wire  late$invalid$2;
    wire  late$invalid$3;
    wire  late$halo$0;
    wire  late$halo$1;
    wire  late$halo$2;
    wire  late$halo$3;
    wire  [31:0] late$ext_addr$0;
    wire  [31:0] late$ext_addr$1;
    wire  [31:0] late$ext_addr$2;
    wire  [31:0] late$ext_addr$3;
    reg  [15:0] late$ext_data$0;
    reg  [15:0] late$ext_data$1;
    reg  [15:0] late$ext_data$2;
    reg  [15:0] late$ext_data$3;
    wire  late$dx_neg$0;
    wire  late$dx_neg$1;
    wire  late$dx_neg$2;
    wire  late$dx_neg$3;
    wire  [15:0] late$dx_mag$0;
    wire  [15:0] late$dx_mag$1;
    wire  [15:0] late$dx_mag$2;
    wire  [15:0] late$dx_mag$3;
    wire  late$dy_neg$0;
    wire  late$dy_neg$1;
    wire  late$dy_neg$2;
    wire  late$dy_neg$3;
    wire  [15:0] late$dy_mag$0;
    wire  [15:0] late$dy_mag$1;
    wire  [15:0] late$dy_mag$2;
    wire  [15:0] late$dy_mag$3;
    reg  [31:0] late_wait$d;
    wire  [31:0] late_wait$q;
    reg  late_wait$clock;
    reg  late_go$d;
    wire  late_go$q;
    reg  late_go$clock;
    reg  [7:0] flush$d;
    wire  [7:0] flush$q;
    reg  flush$clock;
    
    // Local signals
    reg  quiet;
    
    // Sub module instances
    top$view view(
        .clock(view$clock),
        .host_write(view$host_write),
        .host_address(view$host_address),
        .host_data(view$host_data),
        .q$0(view$q$0),
        .q$1(view$q$1),
        .q$2(view$q$2),
        .q$3(view$q$3),
        .q$4(view$q$4),
        .q$5(view$q$5),
        .q$6(view$q$6),
        .q$7(view$q$7),
        .q$8(view$q$8),
        .q$9(view$q$9),
        .q$10(view$q$10)
    );
    top$cfb cfb(
        .clock(cfb$clock),
        .dims(cfb$dims),
        .slices(cfb$slices),
        .axes(cfb$axes),
        .address_reg(cfb$address_reg),
        .dx(cfb$dx),
        .dy(cfb$dy),
        .eye_x(cfb$eye_x),
        .eye_y(cfb$eye_y),
        .eye_z(cfb$eye_z),
        .beats(cfb$beats),
        .start(cfb$start),
        .reset(cfb$reset),
        .busy(cfb$busy),
        .load_enable(cfb$load_enable),
        .load_module(cfb$load_module),
        .load_address(cfb$load_address),
        .load_data(cfb$load_data),
        .valid(cfb$valid),
        .n_s(cfb$n_s),
        .n_beam(cfb$n_beam),
        .n_b(cfb$n_b),
        .bs(cfb$bs),
        .value$0(cfb$value$0),
        .value$1(cfb$value$1),
        .value$2(cfb$value$2),
        .value$3(cfb$value$3),
        .x$0(cfb$x$0),
        .x$1(cfb$x$1),
        .x$2(cfb$x$2),
        .x$3(cfb$x$3),
        .y$0(cfb$y$0),
        .y$1(cfb$y$1),
        .y$2(cfb$y$2),
        .y$3(cfb$y$3),
        .z$0(cfb$z$0),
        .z$1(cfb$z$1),
        .z$2(cfb$z$2),
        .z$3(cfb$z$3),
        .address$0(cfb$address$0),
        .address$1(cfb$address$1),
        .address$2(cfb$address$2),
        .address$3(cfb$address$3),
        .pad$0(cfb$pad$0),
        .pad$1(cfb$pad$1),
        .pad$2(cfb$pad$2),
        .pad$3(cfb$pad$3),
        .sr$0(cfb$sr$0),
        .sr$1(cfb$sr$1),
        .sr$2(cfb$sr$2),
        .sr$3(cfb$sr$3),
        .er$0(cfb$er$0),
        .er$1(cfb$er$1),
        .er$2(cfb$er$2),
        .er$3(cfb$er$3),
        .base_x$0(cfb$base_x$0),
        .base_x$1(cfb$base_x$1),
        .base_x$2(cfb$base_x$2),
        .base_x$3(cfb$base_x$3),
        .base_y$0(cfb$base_y$0),
        .base_y$1(cfb$base_y$1),
        .base_y$2(cfb$base_y$2),
        .base_y$3(cfb$base_y$3),
        .face$0(cfb$face$0),
        .face$1(cfb$face$1),
        .face$2(cfb$face$2),
        .face$3(cfb$face$3),
        .at_edge$0(cfb$at_edge$0),
        .at_edge$1(cfb$at_edge$1),
        .at_edge$2(cfb$at_edge$2),
        .at_edge$3(cfb$at_edge$3),
        .invalid$0(cfb$invalid$0),
        .invalid$1(cfb$invalid$1),
        .invalid$2(cfb$invalid$2),
        .invalid$3(cfb$invalid$3),
        .halo$0(cfb$halo$0),
        .halo$1(cfb$halo$1),
        .halo$2(cfb$halo$2),
        .halo$3(cfb$halo$3),
        .ext_addr$0(cfb$ext_addr$0),
        .ext_addr$1(cfb$ext_addr$1),
        .ext_addr$2(cfb$ext_addr$2),
        .ext_addr$3(cfb$ext_addr$3),
        .ext_data$0(cfb$ext_data$0),
        .ext_data$1(cfb$ext_data$1),
        .ext_data$2(cfb$ext_data$2),
        .ext_data$3(cfb$ext_data$3),
        .dx_neg$0(cfb$dx_neg$0),
        .dx_neg$1(cfb$dx_neg$1),
        .dx_neg$2(cfb$dx_neg$2),
        .dx_neg$3(cfb$dx_neg$3),
        .dx_mag$0(cfb$dx_mag$0),
        .dx_mag$1(cfb$dx_mag$1),
        .dx_mag$2(cfb$dx_mag$2),
        .dx_mag$3(cfb$dx_mag$3),
        .dy_neg$0(cfb$dy_neg$0),
        .dy_neg$1(cfb$dy_neg$1),
        .dy_neg$2(cfb$dy_neg$2),
        .dy_neg$3(cfb$dy_neg$3),
        .dy_mag$0(cfb$dy_mag$0),
        .dy_mag$1(cfb$dy_mag$1),
        .dy_mag$2(cfb$dy_mag$2),
        .dy_mag$3(cfb$dy_mag$3)
    );
    top$lanes$0 lanes$0(
        .clock(lanes$0$clock),
        .host_write(lanes$0$host_write),
        .host_address(lanes$0$host_address),
        .host_data(lanes$0$host_data),
        .dims(lanes$0$dims),
        .beats(lanes$0$beats),
        .order(lanes$0$order),
        .beat_valid(lanes$0$beat_valid),
        .value(lanes$0$value),
        .x(lanes$0$x),
        .y(lanes$0$y),
        .pad(lanes$0$pad),
        .invalid(lanes$0$invalid),
        .halo(lanes$0$halo),
        .sr(lanes$0$sr),
        .er(lanes$0$er),
        .base_x(lanes$0$base_x),
        .base_y(lanes$0$base_y),
        .face(lanes$0$face),
        .at_edge(lanes$0$at_edge),
        .dx_neg(lanes$0$dx_neg),
        .dx_mag(lanes$0$dx_mag),
        .dy_neg(lanes$0$dy_neg),
        .dy_mag(lanes$0$dy_mag),
        .g_from_left_xm(lanes$0$g_from_left_xm),
        .g_from_left_ym(lanes$0$g_from_left_ym),
        .g_from_left_zm(lanes$0$g_from_left_zm),
        .g_from_right_xp(lanes$0$g_from_right_xp),
        .g_from_right_yp(lanes$0$g_from_right_yp),
        .g_from_right_zp(lanes$0$g_from_right_zp),
        .g_to_right_xm(lanes$0$g_to_right_xm),
        .g_to_right_ym(lanes$0$g_to_right_ym),
        .g_to_right_zm(lanes$0$g_to_right_zm),
        .g_to_left_xp(lanes$0$g_to_left_xp),
        .g_to_left_yp(lanes$0$g_to_left_yp),
        .g_to_left_zp(lanes$0$g_to_left_zp),
        .t0s0(lanes$0$t0s0),
        .t0i1(lanes$0$t0i1),
        .t1s0(lanes$0$t1s0),
        .t1s1(lanes$0$t1s1),
        .t1i1(lanes$0$t1i1),
        .t1i2(lanes$0$t1i2),
        .t3s0(lanes$0$t3s0),
        .t3s1(lanes$0$t3s1),
        .t3i1(lanes$0$t3i1),
        .t3i2(lanes$0$t3i2),
        .t5s0(lanes$0$t5s0),
        .t5s1(lanes$0$t5s1),
        .t5s2(lanes$0$t5s2),
        .t5i1(lanes$0$t5i1),
        .t5i2(lanes$0$t5i2),
        .t5i3(lanes$0$t5i3),
        .t6s0(lanes$0$t6s0),
        .t6i1(lanes$0$t6i1),
        .t7s0(lanes$0$t7s0),
        .t7i1(lanes$0$t7i1),
        .t8s0(lanes$0$t8s0),
        .t8i1(lanes$0$t8i1),
        .t8il(lanes$0$t8il),
        .res_beat(lanes$0$res_beat),
        .res_valid(lanes$0$res_valid),
        .res(lanes$0$res),
        .px_valid(lanes$0$px_valid),
        .px_x(lanes$0$px_x),
        .px_y(lanes$0$px_y),
        .px_face(lanes$0$px_face)
    );
    top$lanes$1 lanes$1(
        .clock(lanes$1$clock),
        .host_write(lanes$1$host_write),
        .host_address(lanes$1$host_address),
        .host_data(lanes$1$host_data),
        .dims(lanes$1$dims),
        .beats(lanes$1$beats),
        .order(lanes$1$order),
        .beat_valid(lanes$1$beat_valid),
        .value(lanes$1$value),
        .x(lanes$1$x),
        .y(lanes$1$y),
        .pad(lanes$1$pad),
        .invalid(lanes$1$invalid),
        .halo(lanes$1$halo),
        .sr(lanes$1$sr),
        .er(lanes$1$er),
        .base_x(lanes$1$base_x),
        .base_y(lanes$1$base_y),
        .face(lanes$1$face),
        .at_edge(lanes$1$at_edge),
        .dx_neg(lanes$1$dx_neg),
        .dx_mag(lanes$1$dx_mag),
        .dy_neg(lanes$1$dy_neg),
        .dy_mag(lanes$1$dy_mag),
        .g_from_left_xm(lanes$1$g_from_left_xm),
        .g_from_left_ym(lanes$1$g_from_left_ym),
        .g_from_left_zm(lanes$1$g_from_left_zm),
        .g_from_right_xp(lanes$1$g_from_right_xp),
        .g_from_right_yp(lanes$1$g_from_right_yp),
        .g_from_right_zp(lanes$1$g_from_right_zp),
        .g_to_right_xm(lanes$1$g_to_right_xm),
        .g_to_right_ym(lanes$1$g_to_right_ym),
        .g_to_right_zm(lanes$1$g_to_right_zm),
        .g_to_left_xp(lanes$1$g_to_left_xp),
        .g_to_left_yp(lanes$1$g_to_left_yp),
        .g_to_left_zp(lanes$1$g_to_left_zp),
        .t0s0(lanes$1$t0s0),
        .t0i1(lanes$1$t0i1),
        .t1s0(lanes$1$t1s0),
        .t1s1(lanes$1$t1s1),
        .t1i1(lanes$1$t1i1),
        .t1i2(lanes$1$t1i2),
        .t3s0(lanes$1$t3s0),
        .t3s1(lanes$1$t3s1),
        .t3i1(lanes$1$t3i1),
        .t3i2(lanes$1$t3i2),
        .t5s0(lanes$1$t5s0),
        .t5s1(lanes$1$t5s1),
        .t5s2(lanes$1$t5s2),
        .t5i1(lanes$1$t5i1),
        .t5i2(lanes$1$t5i2),
        .t5i3(lanes$1$t5i3),
        .t6s0(lanes$1$t6s0),
        .t6i1(lanes$1$t6i1),
        .t7s0(lanes$1$t7s0),
        .t7i1(lanes$1$t7i1),
        .t8s0(lanes$1$t8s0),
        .t8i1(lanes$1$t8i1),
        .t8il(lanes$1$t8il),
        .res_beat(lanes$1$res_beat),
        .res_valid(lanes$1$res_valid),
        .res(lanes$1$res),
        .px_valid(lanes$1$px_valid),
        .px_x(lanes$1$px_x),
        .px_y(lanes$1$px_y),
        .px_face(lanes$1$px_face)
    );
    top$lanes$2 lanes$2(
        .clock(lanes$2$clock),
        .host_write(lanes$2$host_write),
        .host_address(lanes$2$host_address),
        .host_data(lanes$2$host_data),
        .dims(lanes$2$dims),
        .beats(lanes$2$beats),
        .order(lanes$2$order),
        .beat_valid(lanes$2$beat_valid),
        .value(lanes$2$value),
        .x(lanes$2$x),
        .y(lanes$2$y),
        .pad(lanes$2$pad),
        .invalid(lanes$2$invalid),
        .halo(lanes$2$halo),
        .sr(lanes$2$sr),
        .er(lanes$2$er),
        .base_x(lanes$2$base_x),
        .base_y(lanes$2$base_y),
        .face(lanes$2$face),
        .at_edge(lanes$2$at_edge),
        .dx_neg(lanes$2$dx_neg),
        .dx_mag(lanes$2$dx_mag),
        .dy_neg(lanes$2$dy_neg),
        .dy_mag(lanes$2$dy_mag),
        .g_from_left_xm(lanes$2$g_from_left_xm),
        .g_from_left_ym(lanes$2$g_from_left_ym),
        .g_from_left_zm(lanes$2$g_from_left_zm),
        .g_from_right_xp(lanes$2$g_from_right_xp),
        .g_from_right_yp(lanes$2$g_from_right_yp),
        .g_from_right_zp(lanes$2$g_from_right_zp),
        .g_to_right_xm(lanes$2$g_to_right_xm),
        .g_to_right_ym(lanes$2$g_to_right_ym),
        .g_to_right_zm(lanes$2$g_to_right_zm),
        .g_to_left_xp(lanes$2$g_to_left_xp),
        .g_to_left_yp(lanes$2$g_to_left_yp),
        .g_to_left_zp(lanes$2$g_to_left_zp),
        .t0s0(lanes$2$t0s0),
        .t0i1(lanes$2$t0i1),
        .t1s0(lanes$2$t1s0),
        .t1s1(lanes$2$t1s1),
        .t1i1(lanes$2$t1i1),
        .t1i2(lanes$2$t1i2),
        .t3s0(lanes$2$t3s0),
        .t3s1(lanes$2$t3s1),
        .t3i1(lanes$2$t3i1),
        .t3i2(lanes$2$t3i2),
        .t5s0(lanes$2$t5s0),
        .t5s1(lanes$2$t5s1),
        .t5s2(lanes$2$t5s2),
        .t5i1(lanes$2$t5i1),
        .t5i2(lanes$2$t5i2),
        .t5i3(lanes$2$t5i3),
        .t6s0(lanes$2$t6s0),
        .t6i1(lanes$2$t6i1),
        .t7s0(lanes$2$t7s0),
        .t7i1(lanes$2$t7i1),
        .t8s0(lanes$2$t8s0),
        .t8i1(lanes$2$t8i1),
        .t8il(lanes$2$t8il),
        .res_beat(lanes$2$res_beat),
        .res_valid(lanes$2$res_valid),
        .res(lanes$2$res),
        .px_valid(lanes$2$px_valid),
        .px_x(lanes$2$px_x),
        .px_y(lanes$2$px_y),
        .px_face(lanes$2$px_face)
    );
    top$lanes$3 lanes$3(
        .clock(lanes$3$clock),
        .host_write(lanes$3$host_write),
        .host_address(lanes$3$host_address),
        .host_data(lanes$3$host_data),
        .dims(lanes$3$dims),
        .beats(lanes$3$beats),
        .order(lanes$3$order),
        .beat_valid(lanes$3$beat_valid),
        .value(lanes$3$value),
        .x(lanes$3$x),
        .y(lanes$3$y),
        .pad(lanes$3$pad),
        .invalid(lanes$3$invalid),
        .halo(lanes$3$halo),
        .sr(lanes$3$sr),
        .er(lanes$3$er),
        .base_x(lanes$3$base_x),
        .base_y(lanes$3$base_y),
        .face(lanes$3$face),
        .at_edge(lanes$3$at_edge),
        .dx_neg(lanes$3$dx_neg),
        .dx_mag(lanes$3$dx_mag),
        .dy_neg(lanes$3$dy_neg),
        .dy_mag(lanes$3$dy_mag),
        .g_from_left_xm(lanes$3$g_from_left_xm),
        .g_from_left_ym(lanes$3$g_from_left_ym),
        .g_from_left_zm(lanes$3$g_from_left_zm),
        .g_from_right_xp(lanes$3$g_from_right_xp),
        .g_from_right_yp(lanes$3$g_from_right_yp),
        .g_from_right_zp(lanes$3$g_from_right_zp),
        .g_to_right_xm(lanes$3$g_to_right_xm),
        .g_to_right_ym(lanes$3$g_to_right_ym),
        .g_to_right_zm(lanes$3$g_to_right_zm),
        .g_to_left_xp(lanes$3$g_to_left_xp),
        .g_to_left_yp(lanes$3$g_to_left_yp),
        .g_to_left_zp(lanes$3$g_to_left_zp),
        .t0s0(lanes$3$t0s0),
        .t0i1(lanes$3$t0i1),
        .t1s0(lanes$3$t1s0),
        .t1s1(lanes$3$t1s1),
        .t1i1(lanes$3$t1i1),
        .t1i2(lanes$3$t1i2),
        .t3s0(lanes$3$t3s0),
        .t3s1(lanes$3$t3s1),
        .t3i1(lanes$3$t3i1),
        .t3i2(lanes$3$t3i2),
        .t5s0(lanes$3$t5s0),
        .t5s1(lanes$3$t5s1),
        .t5s2(lanes$3$t5s2),
        .t5i1(lanes$3$t5i1),
        .t5i2(lanes$3$t5i2),
        .t5i3(lanes$3$t5i3),
        .t6s0(lanes$3$t6s0),
        .t6i1(lanes$3$t6i1),
        .t7s0(lanes$3$t7s0),
        .t7i1(lanes$3$t7i1),
        .t8s0(lanes$3$t8s0),
        .t8i1(lanes$3$t8i1),
        .t8il(lanes$3$t8il),
        .res_beat(lanes$3$res_beat),
        .res_valid(lanes$3$res_valid),
        .res(lanes$3$res),
        .px_valid(lanes$3$px_valid),
        .px_x(lanes$3$px_x),
        .px_y(lanes$3$px_y),
        .px_face(lanes$3$px_face)
    );
    top$late late(
        .clock(late$clock),
        .dims(late$dims),
        .slices(late$slices),
        .axes(late$axes),
        .address_reg(late$address_reg),
        .dx(late$dx),
        .dy(late$dy),
        .eye_x(late$eye_x),
        .eye_y(late$eye_y),
        .eye_z(late$eye_z),
        .beats(late$beats),
        .start(late$start),
        .reset(late$reset),
        .busy(late$busy),
        .load_enable(late$load_enable),
        .load_module(late$load_module),
        .load_address(late$load_address),
        .load_data(late$load_data),
        .valid(late$valid),
        .n_s(late$n_s),
        .n_beam(late$n_beam),
        .n_b(late$n_b),
        .bs(late$bs),
        .value$0(late$value$0),
        .value$1(late$value$1),
        .value$2(late$value$2),
        .value$3(late$value$3),
        .x$0(late$x$0),
        .x$1(late$x$1),
        .x$2(late$x$2),
        .x$3(late$x$3),
        .y$0(late$y$0),
        .y$1(late$y$1),
        .y$2(late$y$2),
        .y$3(late$y$3),
        .z$0(late$z$0),
        .z$1(late$z$1),
        .z$2(late$z$2),
        .z$3(late$z$3),
        .address$0(late$address$0),
        .address$1(late$address$1),
        .address$2(late$address$2),
        .address$3(late$address$3),
        .pad$0(late$pad$0),
        .pad$1(late$pad$1),
        .pad$2(late$pad$2),
        .pad$3(late$pad$3),
        .sr$0(late$sr$0),
        .sr$1(late$sr$1),
        .sr$2(late$sr$2),
        .sr$3(late$sr$3),
        .er$0(late$er$0),
        .er$1(late$er$1),
        .er$2(late$er$2),
        .er$3(late$er$3),
        .base_x$0(late$base_x$0),
        .base_x$1(late$base_x$1),
        .base_x$2(late$base_x$2),
        .base_x$3(late$base_x$3),
        .base_y$0(late$base_y$0),
        .base_y$1(late$base_y$1),
        .base_y$2(late$base_y$2),
        .base_y$3(late$base_y$3),
        .face$0(late$face$0),
        .face$1(late$face$1),
        .face$2(late$face$2),
        .face$3(late$face$3),
        .at_edge$0(late$at_edge$0),
        .at_edge$1(late$at_edge$1),
        .at_edge$2(late$at_edge$2),
        .at_edge$3(late$at_edge$3),
        .invalid$0(late$invalid$0),
        .invalid$1(late$invalid$1),
        .invalid$2(late$invalid$2),
        .invalid$3(late$invalid$3),
        .halo$0(late$halo$0),
        .halo$1(late$halo$1),
        .halo$2(late$halo$2),
        .halo$3(late$halo$3),
        .ext_addr$0(late$ext_addr$0),
        .ext_addr$1(late$ext_addr$1),
        .ext_addr$2(late$ext_addr$2),
        .ext_addr$3(late$ext_addr$3),
        .ext_data$0(late$ext_data$0),
        .ext_data$1(late$ext_data$1),
        .ext_data$2(late$ext_data$2),
        .ext_data$3(late$ext_data$3),
        .dx_neg$0(late$dx_neg$0),
        .dx_neg$1(late$dx_neg$1),
        .dx_neg$2(late$dx_neg$2),
        .dx_neg$3(late$dx_neg$3),
        .dx_mag$0(late$dx_mag$0),
        .dx_mag$1(late$dx_mag$1),
        .dx_mag$2(late$dx_mag$2),
        .dx_mag$3(late$dx_mag$3),
        .dy_neg$0(late$dy_neg$0),
        .dy_neg$1(late$dy_neg$1),
        .dy_neg$2(late$dy_neg$2),
        .dy_neg$3(late$dy_neg$3),
        .dy_mag$0(late$dy_mag$0),
        .dy_mag$1(late$dy_mag$1),
        .dy_mag$2(late$dy_mag$2),
        .dy_mag$3(late$dy_mag$3)
    );
    top$late_wait late_wait(
        .d(late_wait$d),
        .q(late_wait$q),
        .clock(late_wait$clock)
    );
    top$late_go late_go(
        .d(late_go$d),
        .q(late_go$q),
        .clock(late_go$clock)
    );
    top$flush flush(
        .d(flush$d),
        .q(flush$q),
        .clock(flush$clock)
    );
    
    // Update code
    always @(*) begin
        late_wait$clock = clock;
        late_go$clock = clock;
        flush$clock = clock;
        late_wait$d = late_wait$q;
        late_go$d = late_go$q;
        flush$d = flush$q;
        view$clock = clock;
        view$host_write = host_write;
        view$host_address = host_address;
        view$host_data = host_data;
        cfb$dims = view$q$0;
        cfb$slices = view$q$1;
        cfb$axes = view$q$2;
        cfb$address_reg = view$q$3;
        cfb$dx = view$q$4;
        cfb$dy = view$q$5;
        cfb$eye_x = view$q$6;
        cfb$eye_y = view$q$7;
        cfb$eye_z = view$q$8;
        cfb$beats = view$q$9;
        late$dims = view$q$0;
        late$slices = view$q$1;
        late$axes = view$q$2;
        late$address_reg = view$q$3;
        late$dx = view$q$4;
        late$dy = view$q$5;
        late$eye_x = view$q$6;
        late$eye_y = view$q$7;
        late$eye_z = view$q$8;
        late$beats = view$q$9;
        cfb$clock = clock;
        cfb$start = start;
        cfb$reset = reset;
        late$reset = reset;
        flush$d = flush$q;
        if (reset) begin
            flush$d = flush_clocks;
        end
        else if (flush$q != 'h0) begin
            flush$d = flush$q - 'h1;
        end
        quiet = reset | (flush$q != 'h0);
        cfb$load_enable = load_enable;
        cfb$load_module = load_module;
        cfb$load_address = load_address;
        cfb$load_data = load_data;
        busy = cfb$busy;
        n_s = cfb$n_s;
        n_beam = cfb$n_beam;
        n_b = cfb$n_b;
        bs = cfb$bs;
        late_wait$d = late_wait$q;
        if (start & ~cfb$busy) begin
            late_wait$d = view$q$9[('h0)+:(32)] + 'h1;
        end
        else if (late_wait$q != 'h0) begin
            late_wait$d = late_wait$q - 'h1;
        end
        if (reset) begin
            late_wait$d = 'h0;
        end
        late$clock = clock;
        late_go$d = late_wait$d == 'h1;
        late$start = late_go$q;
        late$load_enable = 1'b0;
        late$load_module = 'h0;
        late$load_address = 'h0;
        late$load_data = 'h0;
        late$ext_data$0 = 'h0;
        lanes$0$clock = clock;
        lanes$0$host_write = host_write;
        lanes$0$host_address = host_address;
        lanes$0$host_data = host_data;
        lanes$0$dims = view$q$0;
        lanes$0$beats = view$q$9;
        lanes$0$order = view$q$10;
        cfb$ext_data$0 = ext_data$0;
        ext_addr$0 = cfb$ext_addr$0;
        px_valid$0 = lanes$0$px_valid & ~quiet;
        px_x$0 = lanes$0$px_x;
        px_y$0 = lanes$0$px_y;
        px_face$0 = lanes$0$px_face;
        res_beat$0 = lanes$0$res_beat & ~quiet;
        res_valid$0 = lanes$0$res_valid & ~quiet;
        res$0 = lanes$0$res;
        lanes$0$value = cfb$value$0;
        late$ext_data$1 = 'h0;
        lanes$1$clock = clock;
        lanes$1$host_write = host_write;
        lanes$1$host_address = host_address;
        lanes$1$host_data = host_data;
        lanes$1$dims = view$q$0;
        lanes$1$beats = view$q$9;
        lanes$1$order = view$q$10;
        cfb$ext_data$1 = ext_data$1;
        ext_addr$1 = cfb$ext_addr$1;
        px_valid$1 = lanes$1$px_valid & ~quiet;
        px_x$1 = lanes$1$px_x;
        px_y$1 = lanes$1$px_y;
        px_face$1 = lanes$1$px_face;
        res_beat$1 = lanes$1$res_beat & ~quiet;
        res_valid$1 = lanes$1$res_valid & ~quiet;
        res$1 = lanes$1$res;
        lanes$1$value = cfb$value$1;
        late$ext_data$2 = 'h0;
        lanes$2$clock = clock;
        lanes$2$host_write = host_write;
        lanes$2$host_address = host_address;
        lanes$2$host_data = host_data;
        lanes$2$dims = view$q$0;
        lanes$2$beats = view$q$9;
        lanes$2$order = view$q$10;
        cfb$ext_data$2 = ext_data$2;
        ext_addr$2 = cfb$ext_addr$2;
        px_valid$2 = lanes$2$px_valid & ~quiet;
        px_x$2 = lanes$2$px_x;
        px_y$2 = lanes$2$px_y;
        px_face$2 = lanes$2$px_face;
        res_beat$2 = lanes$2$res_beat & ~quiet;
        res_valid$2 = lanes$2$res_valid & ~quiet;
        res$2 = lanes$2$res;
        lanes$2$value = cfb$value$2;
        late$ext_data$3 = 'h0;
        lanes$3$clock = clock;
        lanes$3$host_write = host_write;
        lanes$3$host_address = host_address;
        lanes$3$host_data = host_data;
        lanes$3$dims = view$q$0;
        lanes$3$beats = view$q$9;
        lanes$3$order = view$q$10;
        cfb$ext_data$3 = ext_data$3;
        ext_addr$3 = cfb$ext_addr$3;
        px_valid$3 = lanes$3$px_valid & ~quiet;
        px_x$3 = lanes$3$px_x;
        px_y$3 = lanes$3$px_y;
        px_face$3 = lanes$3$px_face;
        res_beat$3 = lanes$3$res_beat & ~quiet;
        res_valid$3 = lanes$3$res_valid & ~quiet;
        res$3 = lanes$3$res;
        lanes$3$value = cfb$value$3;
        if (gradient) begin
            lanes$0$beat_valid = late$valid;
            lanes$0$x = late$x$0;
            lanes$0$y = late$y$0;
            lanes$0$pad = late$pad$0;
            lanes$0$invalid = late$invalid$0;
            lanes$0$halo = late$halo$0;
            lanes$0$sr = late$sr$0;
            lanes$0$er = late$er$0;
            lanes$0$base_x = late$base_x$0;
            lanes$0$base_y = late$base_y$0;
            lanes$0$face = late$face$0;
            lanes$0$at_edge = late$at_edge$0;
            lanes$0$dx_neg = late$dx_neg$0;
            lanes$0$dx_mag = late$dx_mag$0;
            lanes$0$dy_neg = late$dy_neg$0;
            lanes$0$dy_mag = late$dy_mag$0;
            lanes$1$beat_valid = late$valid;
            lanes$1$x = late$x$1;
            lanes$1$y = late$y$1;
            lanes$1$pad = late$pad$1;
            lanes$1$invalid = late$invalid$1;
            lanes$1$halo = late$halo$1;
            lanes$1$sr = late$sr$1;
            lanes$1$er = late$er$1;
            lanes$1$base_x = late$base_x$1;
            lanes$1$base_y = late$base_y$1;
            lanes$1$face = late$face$1;
            lanes$1$at_edge = late$at_edge$1;
            lanes$1$dx_neg = late$dx_neg$1;
            lanes$1$dx_mag = late$dx_mag$1;
            lanes$1$dy_neg = late$dy_neg$1;
            lanes$1$dy_mag = late$dy_mag$1;
            lanes$2$beat_valid = late$valid;
            lanes$2$x = late$x$2;
            lanes$2$y = late$y$2;
            lanes$2$pad = late$pad$2;
            lanes$2$invalid = late$invalid$2;
            lanes$2$halo = late$halo$2;
            lanes$2$sr = late$sr$2;
            lanes$2$er = late$er$2;
            lanes$2$base_x = late$base_x$2;
            lanes$2$base_y = late$base_y$2;
            lanes$2$face = late$face$2;
            lanes$2$at_edge = late$at_edge$2;
            lanes$2$dx_neg = late$dx_neg$2;
            lanes$2$dx_mag = late$dx_mag$2;
            lanes$2$dy_neg = late$dy_neg$2;
            lanes$2$dy_mag = late$dy_mag$2;
            lanes$3$beat_valid = late$valid;
            lanes$3$x = late$x$3;
            lanes$3$y = late$y$3;
            lanes$3$pad = late$pad$3;
            lanes$3$invalid = late$invalid$3;
            lanes$3$halo = late$halo$3;
            lanes$3$sr = late$sr$3;
            lanes$3$er = late$er$3;
            lanes$3$base_x = late$base_x$3;
            lanes$3$base_y = late$base_y$3;
            lanes$3$face = late$face$3;
            lanes$3$at_edge = late$at_edge$3;
            lanes$3$dx_neg = late$dx_neg$3;
            lanes$3$dx_mag = late$dx_mag$3;
            lanes$3$dy_neg = late$dy_neg$3;
            lanes$3$dy_mag = late$dy_mag$3;
        end
        else begin
            lanes$0$beat_valid = cfb$valid;
            lanes$0$x = cfb$x$0;
            lanes$0$y = cfb$y$0;
            lanes$0$pad = cfb$pad$0;
            lanes$0$invalid = cfb$invalid$0;
            lanes$0$halo = cfb$halo$0;
            lanes$0$sr = cfb$sr$0;
            lanes$0$er = cfb$er$0;
            lanes$0$base_x = cfb$base_x$0;
            lanes$0$base_y = cfb$base_y$0;
            lanes$0$face = cfb$face$0;
            lanes$0$at_edge = cfb$at_edge$0;
            lanes$0$dx_neg = cfb$dx_neg$0;
            lanes$0$dx_mag = cfb$dx_mag$0;
            lanes$0$dy_neg = cfb$dy_neg$0;
            lanes$0$dy_mag = cfb$dy_mag$0;
            lanes$1$beat_valid = cfb$valid;
            lanes$1$x = cfb$x$1;
            lanes$1$y = cfb$y$1;
            lanes$1$pad = cfb$pad$1;
            lanes$1$invalid = cfb$invalid$1;
            lanes$1$halo = cfb$halo$1;
            lanes$1$sr = cfb$sr$1;
            lanes$1$er = cfb$er$1;
            lanes$1$base_x = cfb$base_x$1;
            lanes$1$base_y = cfb$base_y$1;
            lanes$1$face = cfb$face$1;
            lanes$1$at_edge = cfb$at_edge$1;
            lanes$1$dx_neg = cfb$dx_neg$1;
            lanes$1$dx_mag = cfb$dx_mag$1;
            lanes$1$dy_neg = cfb$dy_neg$1;
            lanes$1$dy_mag = cfb$dy_mag$1;
            lanes$2$beat_valid = cfb$valid;
            lanes$2$x = cfb$x$2;
            lanes$2$y = cfb$y$2;
            lanes$2$pad = cfb$pad$2;
            lanes$2$invalid = cfb$invalid$2;
            lanes$2$halo = cfb$halo$2;
            lanes$2$sr = cfb$sr$2;
            lanes$2$er = cfb$er$2;
            lanes$2$base_x = cfb$base_x$2;
            lanes$2$base_y = cfb$base_y$2;
            lanes$2$face = cfb$face$2;
            lanes$2$at_edge = cfb$at_edge$2;
            lanes$2$dx_neg = cfb$dx_neg$2;
            lanes$2$dx_mag = cfb$dx_mag$2;
            lanes$2$dy_neg = cfb$dy_neg$2;
            lanes$2$dy_mag = cfb$dy_mag$2;
            lanes$3$beat_valid = cfb$valid;
            lanes$3$x = cfb$x$3;
            lanes$3$y = cfb$y$3;
            lanes$3$pad = cfb$pad$3;
            lanes$3$invalid = cfb$invalid$3;
            lanes$3$halo = cfb$halo$3;
            lanes$3$sr = cfb$sr$3;
            lanes$3$er = cfb$er$3;
            lanes$3$base_x = cfb$base_x$3;
            lanes$3$base_y = cfb$base_y$3;
            lanes$3$face = cfb$face$3;
            lanes$3$at_edge = cfb$at_edge$3;
            lanes$3$dx_neg = cfb$dx_neg$3;
            lanes$3$dx_mag = cfb$dx_mag$3;
            lanes$3$dy_neg = cfb$dy_neg$3;
            lanes$3$dy_mag = cfb$dy_mag$3;
        end
        lanes$1$t0i1 = lanes$0$t0s0;
        lanes$1$t1i1 = lanes$0$t1s0;
        lanes$1$t1i2 = lanes$0$t1s1;
        lanes$1$t3i1 = lanes$0$t3s0;
        lanes$1$t3i2 = lanes$0$t3s1;
        lanes$1$t5i1 = lanes$0$t5s0;
        lanes$1$t5i2 = lanes$0$t5s1;
        lanes$1$t5i3 = lanes$0$t5s2;
        lanes$1$t6i1 = lanes$0$t6s0;
        lanes$1$t7i1 = lanes$0$t7s0;
        lanes$1$t8i1 = lanes$0$t8s0;
        lanes$2$t0i1 = lanes$1$t0s0;
        lanes$2$t1i1 = lanes$1$t1s0;
        lanes$2$t1i2 = lanes$1$t1s1;
        lanes$2$t3i1 = lanes$1$t3s0;
        lanes$2$t3i2 = lanes$1$t3s1;
        lanes$2$t5i1 = lanes$1$t5s0;
        lanes$2$t5i2 = lanes$1$t5s1;
        lanes$2$t5i3 = lanes$1$t5s2;
        lanes$2$t6i1 = lanes$1$t6s0;
        lanes$2$t7i1 = lanes$1$t7s0;
        lanes$2$t8i1 = lanes$1$t8s0;
        lanes$3$t0i1 = lanes$2$t0s0;
        lanes$3$t1i1 = lanes$2$t1s0;
        lanes$3$t1i2 = lanes$2$t1s1;
        lanes$3$t3i1 = lanes$2$t3s0;
        lanes$3$t3i2 = lanes$2$t3s1;
        lanes$3$t5i1 = lanes$2$t5s0;
        lanes$3$t5i2 = lanes$2$t5s1;
        lanes$3$t5i3 = lanes$2$t5s2;
        lanes$3$t6i1 = lanes$2$t6s0;
        lanes$3$t7i1 = lanes$2$t7s0;
        lanes$3$t8i1 = lanes$2$t8s0;
        lanes$0$t0i1 = lanes$3$t0s0;
        lanes$0$t1i1 = lanes$3$t1s0;
        lanes$0$t1i2 = lanes$3$t1s1;
        lanes$0$t3i1 = lanes$3$t3s0;
        lanes$0$t3i2 = lanes$3$t3s1;
        lanes$0$t5i1 = lanes$3$t5s0;
        lanes$0$t5i2 = lanes$3$t5s1;
        lanes$0$t5i3 = lanes$3$t5s2;
        lanes$0$t6i1 = lanes$3$t6s0;
        lanes$0$t7i1 = lanes$3$t7s0;
        lanes$0$t8i1 = lanes$3$t8s0;
        lanes$0$t8il = lanes$1$t8s0;
        lanes$1$t8il = lanes$2$t8s0;
        lanes$2$t8il = lanes$3$t8s0;
        lanes$3$t8il = lanes$0$t8s0;
        lanes$1$g_from_left_xm = lanes$0$g_to_right_xm;
        lanes$1$g_from_left_ym = lanes$0$g_to_right_ym;
        lanes$1$g_from_left_zm = lanes$0$g_to_right_zm;
        lanes$2$g_from_left_xm = lanes$1$g_to_right_xm;
        lanes$2$g_from_left_ym = lanes$1$g_to_right_ym;
        lanes$2$g_from_left_zm = lanes$1$g_to_right_zm;
        lanes$3$g_from_left_xm = lanes$2$g_to_right_xm;
        lanes$3$g_from_left_ym = lanes$2$g_to_right_ym;
        lanes$3$g_from_left_zm = lanes$2$g_to_right_zm;
        lanes$0$g_from_left_xm = lanes$3$g_to_right_xm;
        lanes$0$g_from_left_ym = lanes$3$g_to_right_ym;
        lanes$0$g_from_left_zm = lanes$3$g_to_right_zm;
        lanes$0$g_from_right_xp = lanes$1$g_to_left_xp;
        lanes$0$g_from_right_yp = lanes$1$g_to_left_yp;
        lanes$0$g_from_right_zp = lanes$1$g_to_left_zp;
        lanes$1$g_from_right_xp = lanes$2$g_to_left_xp;
        lanes$1$g_from_right_yp = lanes$2$g_to_left_yp;
        lanes$1$g_from_right_zp = lanes$2$g_to_left_zp;
        lanes$2$g_from_right_xp = lanes$3$g_to_left_xp;
        lanes$2$g_from_right_yp = lanes$3$g_to_left_yp;
        lanes$2$g_from_right_zp = lanes$3$g_to_left_zp;
        lanes$3$g_from_right_xp = lanes$0$g_to_left_xp;
        lanes$3$g_from_right_yp = lanes$0$g_to_left_yp;
        lanes$3$g_from_right_zp = lanes$0$g_to_left_zp;
    end
    
endmodule // top
