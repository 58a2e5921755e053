module top$cfb(clock,dims,slices,axes,address_reg,dx,dy,eye_x,eye_y,eye_z,beats,start,reset,busy,load_enable,load_module,load_address,load_data,valid,n_s,n_beam,n_b,bs,value$0,value$1,x$0,x$1,y$0,y$1,z$0,z$1,address$0,address$1,pad$0,pad$1,sr$0,sr$1,er$0,er$1,base_x$0,base_x$1,base_y$0,base_y$1,face$0,face$1,at_edge$0,at_edge$1,invalid$0,invalid$1,halo$0,halo$1,ext_addr$0,ext_addr$1,ext_data$0,ext_data$1,dx_neg$0,dx_neg$1,dx_mag$0,dx_mag$1,dy_neg$0,dy_neg$1,dy_mag$0,dy_mag$1);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] dims;
    input wire  [63:0] slices;
    input wire  [63:0] axes;
    input wire  [63:0] address_reg;
    input wire  [63:0] dx;
    input wire  [63:0] dy;
    input wire  [63:0] eye_x;
    input wire  [63:0] eye_y;
    input wire  [63:0] eye_z;
    input wire  [63:0] beats;
    input wire  start;
    input wire  reset;
    output reg  busy;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [15:0] load_address;
    input wire  [15:0] load_data;
    output reg  valid;
    output reg  [15:0] n_s;
    output reg  [15:0] n_beam;
    output reg  [15:0] n_b;
    output reg  bs;
    output reg  [15:0] value$0;
    output reg  [15:0] value$1;
    output reg  [15:0] x$0;
    output reg  [15:0] x$1;
    output reg  [15:0] y$0;
    output reg  [15:0] y$1;
    output reg  [15:0] z$0;
    output reg  [15:0] z$1;
    output reg  [31:0] address$0;
    output reg  [31:0] address$1;
    output reg  pad$0;
    output reg  pad$1;
    output reg  sr$0;
    output reg  sr$1;
    output reg  er$0;
    output reg  er$1;
    output reg  [15:0] base_x$0;
    output reg  [15:0] base_x$1;
    output reg  [15:0] base_y$0;
    output reg  [15:0] base_y$1;
    output reg  [2:0] face$0;
    output reg  [2:0] face$1;
    output reg  at_edge$0;
    output reg  at_edge$1;
    output reg  invalid$0;
    output reg  invalid$1;
    output reg  halo$0;
    output reg  halo$1;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    output reg  dx_neg$0;
    output reg  dx_neg$1;
    output reg  [15:0] dx_mag$0;
    output reg  [15:0] dx_mag$1;
    output reg  dy_neg$0;
    output reg  dy_neg$1;
    output reg  [15:0] dy_mag$0;
    output reg  [15:0] dy_mag$1;
    
    // Constant declarations
    localparam  perspective = 1'b1;
    
    // Stub signals
    reg  lanes$0$clock;
    reg  [63:0] lanes$0$dims;
    reg  [63:0] lanes$0$slices;
    reg  [63:0] lanes$0$axes;
    reg  [63:0] lanes$0$address_reg;
    reg  [63:0] lanes$0$dx;
    reg  [63:0] lanes$0$dy;
    reg  [63:0] lanes$0$eye_x;
    reg  [63:0] lanes$0$eye_y;
    reg  [63:0] lanes$0$eye_z;
    reg  [15:0] lanes$0$d_n_s;
    reg  [15:0] lanes$0$d_n_beam;
    reg  [15:0] lanes$0$d_n_b;
    reg  [15:0] lanes$0$a_n_s;
    reg  [15:0] lanes$0$a_n_beam;
    reg  [15:0] lanes$0$a_n_b;
    reg  [15:0] lanes$0$c_n_s;
    reg  [15:0] lanes$0$c_n_beam;
    reg  [15:0] lanes$0$c_n_b;
    reg  [15:0] lanes$0$n_s;
    reg  [15:0] lanes$0$n_beam;
    reg  lanes$0$load_enable;
    reg  [7:0] lanes$0$load_module;
    reg  [15:0] lanes$0$load_address;
    reg  [15:0] lanes$0$load_data;
    wire  [31:0] lanes$0$ext_addr;
    reg  [15:0] lanes$0$ext_data;
    wire  [15:0] lanes$0$value;
    wire  [15:0] lanes$0$x;
    wire  [15:0] lanes$0$y;
    wire  [15:0] lanes$0$z;
    wire  [31:0] lanes$0$address;
    wire  lanes$0$pad;
    wire  lanes$0$sr;
    wire  lanes$0$er;
    wire  lanes$0$at_edge;
    wire  [2:0] lanes$0$face;
    wire  [15:0] lanes$0$base_x;
    wire  [15:0] lanes$0$base_y;
    wire  lanes$0$halo;
    wire  lanes$0$dx_neg;
    wire  [15:0] lanes$0$dx_mag;
    wire  lanes$0$dy_neg;
    wire  [15:0] lanes$0$dy_mag;
    wire  lanes$0$invalid;
    reg  lanes$1$clock;
    reg  [63:0] lanes$1$dims;
    reg  [63:0] lanes$1$slices;
    reg  [63:0] lanes$1$axes;
    reg  [63:0] lanes$1$address_reg;
    reg  [63:0] lanes$1$dx;
    reg  [63:0] lanes$1$dy;
    reg  [63:0] lanes$1$eye_x;
    reg  [63:0] lanes$1$eye_y;
    reg  [63:0] lanes$1$eye_z;
    reg  [15:0] lanes$1$d_n_s;
    reg  [15:0] lanes$1$d_n_beam;
    reg  [15:0] lanes$1$d_n_b;
    reg  [15:0] lanes$1$a_n_s;
    reg  [15:0] lanes$1$a_n_beam;
    reg  [15:0] lanes$1$a_n_b;
    reg  [15:0] lanes$1$c_n_s;
    reg  [15:0] lanes$1$c_n_beam;
    reg  [15:0] lanes$1$c_n_b;
    reg  [15:0] lanes$1$n_s;
    reg  [15:0] lanes$1$n_beam;
    reg  lanes$1$load_enable;
    reg  [7:0] lanes$1$load_module;
    reg  [15:0] lanes$1$load_address;
    reg  [15:0] lanes$1$load_data;
    wire  [31:0] lanes$1$ext_addr;
    reg  [15:0] lanes$1$ext_data;
    wire  [15:0] lanes$1$value;
    wire  [15:0] lanes$1$x;
    wire  [15:0] lanes$1$y;
    wire  [15:0] lanes$1$z;
    wire  [31:0] lanes$1$address;
    wire  lanes$1$pad;
    wire  lanes$1$sr;
    wire  lanes$1$er;
    wire  lanes$1$at_edge;
    wire  [2:0] lanes$1$face;
    wire  [15:0] lanes$1$base_x;
    wire  [15:0] lanes$1$base_y;
    wire  lanes$1$halo;
    wire  lanes$1$dx_neg;
    wire  [15:0] lanes$1$dx_mag;
    wire  lanes$1$dy_neg;
    wire  [15:0] lanes$1$dy_mag;
    wire  lanes$1$invalid;
    reg  running$d;
    wire  running$q;
    reg  running$clock;
    reg  [15:0] ns_c$d;
    wire  [15:0] ns_c$q;
    reg  ns_c$clock;
    reg  [15:0] nbeam_c$d;
    wire  [15:0] nbeam_c$q;
    reg  nbeam_c$clock;
    reg  [15:0] nb_c$d;
    wire  [15:0] nb_c$q;
    reg  nb_c$clock;
    reg  lead$clock;
    reg  lead$reset;
    reg  lead$running;
    reg  [15:0] lead$n_s;
    reg  [15:0] lead$n_beam;
    reg  [15:0] lead$n_b;
    wire  lead$running_out;
    wire  [15:0] lead$n_s_out;
    wire  [15:0] lead$n_beam_out;
    wire  [15:0] lead$n_b_out;
    wire  lead$busy;
    reg  run_d1$d;
    wire  run_d1$q;
    reg  run_d1$clock;
    reg  run_d2$d;
    wire  run_d2$q;
    reg  run_d2$clock;
    reg  run_d3$d;
    wire  run_d3$q;
    reg  run_d3$clock;
    reg  [15:0] ns_d1$d;
    wire  [15:0] ns_d1$q;
    reg  ns_d1$clock;
    reg  [15:0] ns_d2$d;
    wire  [15:0] ns_d2$q;
    reg  ns_d2$clock;
    reg  [15:0] ns_d3$d;
    wire  [15:0] ns_d3$q;
    reg  ns_d3$clock;
    reg  [15:0] nbeam_d1$d;
    wire  [15:0] nbeam_d1$q;
    reg  nbeam_d1$clock;
    reg  [15:0] nbeam_d2$d;
    wire  [15:0] nbeam_d2$q;
    reg  nbeam_d2$clock;
    reg  [15:0] nbeam_d3$d;
    wire  [15:0] nbeam_d3$q;
    reg  nbeam_d3$clock;
    reg  [15:0] nb_d1$d;
    wire  [15:0] nb_d1$q;
    reg  nb_d1$clock;
    reg  [15:0] nb_d2$d;
    wire  [15:0] nb_d2$q;
    reg  nb_d2$clock;
    reg  [15:0] nb_d3$d;
    wire  [15:0] nb_d3$q;
    reg  nb_d3$clock;
    reg  run_d4$d;
    wire  run_d4$q;
    reg  run_d4$clock;
    reg  [15:0] ns_d4$d;
    wire  [15:0] ns_d4$q;
    reg  ns_d4$clock;
    reg  [15:0] nbeam_d4$d;
    wire  [15:0] nbeam_d4$q;
    reg  nbeam_d4$clock;
    reg  [15:0] nb_d4$d;
    wire  [15:0] nb_d4$q;
    reg  nb_d4$clock;
    reg  run_d5$d;
    wire  run_d5$q;
    reg  run_d5$clock;
    reg  [15:0] ns_d5$d;
    wire  [15:0] ns_d5$q;
    reg  ns_d5$clock;
    reg  [15:0] nbeam_d5$d;
    wire  [15:0] nbeam_d5$q;
    reg  nbeam_d5$clock;
    reg  [15:0] nb_d5$d;
    wire  [15:0] nb_d5$q;
    reg  nb_d5$clock;
    reg  valid_q$d;
    wire  valid_q$q;
    reg  valid_q$clock;
    reg  [15:0] ns_q$d;
    wire  [15:0] ns_q$q;
    reg  ns_q$clock;
    reg  [15:0] nbeam_q$d;
    wire  [15:0] nbeam_q$q;
    reg  nbeam_q$clock;
    reg  [15:0] nb_q$d;
    wire  [15:0] nb_q$q;
    reg  nb_q$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [15:0] b_last$d;
    wire  [15:0] b_last$q;
    reg  b_last$clock;
    reg  [15:0] nb_left$d;
    wire  [15:0] nb_left$q;
    reg  nb_left$clock;
    reg  [15:0] nbeam_left$d;
    wire  [15:0] nbeam_left$q;
    reg  nbeam_left$clock;
    reg  [15:0] ns_left$d;
    wire  [15:0] ns_left$q;
    reg  ns_left$clock;
    reg  nb_end$d;
    wire  nb_end$q;
    reg  nb_end$clock;
    reg  nbeam_end$d;
    wire  nbeam_end$q;
    reg  nbeam_end$clock;
    reg  ns_end$d;
    wire  ns_end$q;
    reg  ns_end$clock;
    reg  ny_last_zero$d;
    wire  ny_last_zero$q;
    reg  ny_last_zero$clock;
    reg  b_last_zero$d;
    wire  b_last_zero$q;
    reg  b_last_zero$clock;
    
    // Local signals
    reg  e_run;
    reg  [15:0] e_ns;
    reg  [15:0] e_nbeam;
    reg  [15:0] e_nb;
    reg  [15:0] z0;
    reg  [15:0] z1;
    reg  [15:0] ny_m1;
    reg  [15:0] b_m1;
    
    // Sub module instances
    top$cfb$lanes$0 lanes$0(
        .clock(lanes$0$clock),
        .dims(lanes$0$dims),
        .slices(lanes$0$slices),
        .axes(lanes$0$axes),
        .address_reg(lanes$0$address_reg),
        .dx(lanes$0$dx),
        .dy(lanes$0$dy),
        .eye_x(lanes$0$eye_x),
        .eye_y(lanes$0$eye_y),
        .eye_z(lanes$0$eye_z),
        .d_n_s(lanes$0$d_n_s),
        .d_n_beam(lanes$0$d_n_beam),
        .d_n_b(lanes$0$d_n_b),
        .a_n_s(lanes$0$a_n_s),
        .a_n_beam(lanes$0$a_n_beam),
        .a_n_b(lanes$0$a_n_b),
        .c_n_s(lanes$0$c_n_s),
        .c_n_beam(lanes$0$c_n_beam),
        .c_n_b(lanes$0$c_n_b),
        .n_s(lanes$0$n_s),
        .n_beam(lanes$0$n_beam),
        .load_enable(lanes$0$load_enable),
        .load_module(lanes$0$load_module),
        .load_address(lanes$0$load_address),
        .load_data(lanes$0$load_data),
        .ext_addr(lanes$0$ext_addr),
        .ext_data(lanes$0$ext_data),
        .value(lanes$0$value),
        .x(lanes$0$x),
        .y(lanes$0$y),
        .z(lanes$0$z),
        .address(lanes$0$address),
        .pad(lanes$0$pad),
        .sr(lanes$0$sr),
        .er(lanes$0$er),
        .at_edge(lanes$0$at_edge),
        .face(lanes$0$face),
        .base_x(lanes$0$base_x),
        .base_y(lanes$0$base_y),
        .halo(lanes$0$halo),
        .dx_neg(lanes$0$dx_neg),
        .dx_mag(lanes$0$dx_mag),
        .dy_neg(lanes$0$dy_neg),
        .dy_mag(lanes$0$dy_mag),
        .invalid(lanes$0$invalid)
    );
    top$cfb$lanes$1 lanes$1(
        .clock(lanes$1$clock),
        .dims(lanes$1$dims),
        .slices(lanes$1$slices),
        .axes(lanes$1$axes),
        .address_reg(lanes$1$address_reg),
        .dx(lanes$1$dx),
        .dy(lanes$1$dy),
        .eye_x(lanes$1$eye_x),
        .eye_y(lanes$1$eye_y),
        .eye_z(lanes$1$eye_z),
        .d_n_s(lanes$1$d_n_s),
        .d_n_beam(lanes$1$d_n_beam),
        .d_n_b(lanes$1$d_n_b),
        .a_n_s(lanes$1$a_n_s),
        .a_n_beam(lanes$1$a_n_beam),
        .a_n_b(lanes$1$a_n_b),
        .c_n_s(lanes$1$c_n_s),
        .c_n_beam(lanes$1$c_n_beam),
        .c_n_b(lanes$1$c_n_b),
        .n_s(lanes$1$n_s),
        .n_beam(lanes$1$n_beam),
        .load_enable(lanes$1$load_enable),
        .load_module(lanes$1$load_module),
        .load_address(lanes$1$load_address),
        .load_data(lanes$1$load_data),
        .ext_addr(lanes$1$ext_addr),
        .ext_data(lanes$1$ext_data),
        .value(lanes$1$value),
        .x(lanes$1$x),
        .y(lanes$1$y),
        .z(lanes$1$z),
        .address(lanes$1$address),
        .pad(lanes$1$pad),
        .sr(lanes$1$sr),
        .er(lanes$1$er),
        .at_edge(lanes$1$at_edge),
        .face(lanes$1$face),
        .base_x(lanes$1$base_x),
        .base_y(lanes$1$base_y),
        .halo(lanes$1$halo),
        .dx_neg(lanes$1$dx_neg),
        .dx_mag(lanes$1$dx_mag),
        .dy_neg(lanes$1$dy_neg),
        .dy_mag(lanes$1$dy_mag),
        .invalid(lanes$1$invalid)
    );
    top$cfb$running running(
        .d(running$d),
        .q(running$q),
        .clock(running$clock)
    );
    top$cfb$ns_c ns_c(
        .d(ns_c$d),
        .q(ns_c$q),
        .clock(ns_c$clock)
    );
    top$cfb$nbeam_c nbeam_c(
        .d(nbeam_c$d),
        .q(nbeam_c$q),
        .clock(nbeam_c$clock)
    );
    top$cfb$nb_c nb_c(
        .d(nb_c$d),
        .q(nb_c$q),
        .clock(nb_c$clock)
    );
    top$cfb$lead lead(
        .clock(lead$clock),
        .reset(lead$reset),
        .running(lead$running),
        .n_s(lead$n_s),
        .n_beam(lead$n_beam),
        .n_b(lead$n_b),
        .running_out(lead$running_out),
        .n_s_out(lead$n_s_out),
        .n_beam_out(lead$n_beam_out),
        .n_b_out(lead$n_b_out),
        .busy(lead$busy)
    );
    top$cfb$run_d1 run_d1(
        .d(run_d1$d),
        .q(run_d1$q),
        .clock(run_d1$clock)
    );
    top$cfb$run_d2 run_d2(
        .d(run_d2$d),
        .q(run_d2$q),
        .clock(run_d2$clock)
    );
    top$cfb$run_d3 run_d3(
        .d(run_d3$d),
        .q(run_d3$q),
        .clock(run_d3$clock)
    );
    top$cfb$ns_d1 ns_d1(
        .d(ns_d1$d),
        .q(ns_d1$q),
        .clock(ns_d1$clock)
    );
    top$cfb$ns_d2 ns_d2(
        .d(ns_d2$d),
        .q(ns_d2$q),
        .clock(ns_d2$clock)
    );
    top$cfb$ns_d3 ns_d3(
        .d(ns_d3$d),
        .q(ns_d3$q),
        .clock(ns_d3$clock)
    );
    top$cfb$nbeam_d1 nbeam_d1(
        .d(nbeam_d1$d),
        .q(nbeam_d1$q),
        .clock(nbeam_d1$clock)
    );
    top$cfb$nbeam_d2 nbeam_d2(
        .d(nbeam_d2$d),
        .q(nbeam_d2$q),
        .clock(nbeam_d2$clock)
    );
    top$cfb$nbeam_d3 nbeam_d3(
        .d(nbeam_d3$d),
        .q(nbeam_d3$q),
        .clock(nbeam_d3$clock)
    );
    top$cfb$nb_d1 nb_d1(
        .d(nb_d1$d),
        .q(nb_d1$q),
        .clock(nb_d1$clock)
    );
    top$cfb$nb_d2 nb_d2(
        .d(nb_d2$d),
        .q(nb_d2$q),
        .clock(nb_d2$clock)
    );
    top$cfb$nb_d3 nb_d3(
        .d(nb_d3$d),
        .q(nb_d3$q),
        .clock(nb_d3$clock)
    );
    top$cfb$run_d4 run_d4(
        .d(run_d4$d),
        .q(run_d4$q),
        .clock(run_d4$clock)
    );
    top$cfb$ns_d4 ns_d4(
        .d(ns_d4$d),
        .q(ns_d4$q),
        .clock(ns_d4$clock)
    );
    top$cfb$nbeam_d4 nbeam_d4(
        .d(nbeam_d4$d),
        .q(nbeam_d4$q),
        .clock(nbeam_d4$clock)
    );
    top$cfb$nb_d4 nb_d4(
        .d(nb_d4$d),
        .q(nb_d4$q),
        .clock(nb_d4$clock)
    );
    top$cfb$run_d5 run_d5(
        .d(run_d5$d),
        .q(run_d5$q),
        .clock(run_d5$clock)
    );
    top$cfb$ns_d5 ns_d5(
        .d(ns_d5$d),
        .q(ns_d5$q),
        .clock(ns_d5$clock)
    );
    top$cfb$nbeam_d5 nbeam_d5(
        .d(nbeam_d5$d),
        .q(nbeam_d5$q),
        .clock(nbeam_d5$clock)
    );
    top$cfb$nb_d5 nb_d5(
        .d(nb_d5$d),
        .q(nb_d5$q),
        .clock(nb_d5$clock)
    );
    top$cfb$valid_q valid_q(
        .d(valid_q$d),
        .q(valid_q$q),
        .clock(valid_q$clock)
    );
    top$cfb$ns_q ns_q(
        .d(ns_q$d),
        .q(ns_q$q),
        .clock(ns_q$clock)
    );
    top$cfb$nbeam_q nbeam_q(
        .d(nbeam_q$d),
        .q(nbeam_q$q),
        .clock(nbeam_q$clock)
    );
    top$cfb$nb_q nb_q(
        .d(nb_q$d),
        .q(nb_q$q),
        .clock(nb_q$clock)
    );
    top$cfb$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$cfb$b_last b_last(
        .d(b_last$d),
        .q(b_last$q),
        .clock(b_last$clock)
    );
    top$cfb$nb_left nb_left(
        .d(nb_left$d),
        .q(nb_left$q),
        .clock(nb_left$clock)
    );
    top$cfb$nbeam_left nbeam_left(
        .d(nbeam_left$d),
        .q(nbeam_left$q),
        .clock(nbeam_left$clock)
    );
    top$cfb$ns_left ns_left(
        .d(ns_left$d),
        .q(ns_left$q),
        .clock(ns_left$clock)
    );
    top$cfb$nb_end nb_end(
        .d(nb_end$d),
        .q(nb_end$q),
        .clock(nb_end$clock)
    );
    top$cfb$nbeam_end nbeam_end(
        .d(nbeam_end$d),
        .q(nbeam_end$q),
        .clock(nbeam_end$clock)
    );
    top$cfb$ns_end ns_end(
        .d(ns_end$d),
        .q(ns_end$q),
        .clock(ns_end$clock)
    );
    top$cfb$ny_last_zero ny_last_zero(
        .d(ny_last_zero$d),
        .q(ny_last_zero$q),
        .clock(ny_last_zero$clock)
    );
    top$cfb$b_last_zero b_last_zero(
        .d(b_last_zero$d),
        .q(b_last_zero$q),
        .clock(b_last_zero$clock)
    );
    
    // Update code
    reg  busy_pass;
    always @(*) begin
        running$clock = clock;
        ns_c$clock = clock;
        nbeam_c$clock = clock;
        nb_c$clock = clock;
        valid_q$clock = clock;
        ns_q$clock = clock;
        nbeam_q$clock = clock;
        nb_q$clock = clock;
        run_d1$clock = clock;
        run_d2$clock = clock;
        run_d3$clock = clock;
        run_d4$clock = clock;
        ns_d1$clock = clock;
        ns_d2$clock = clock;
        ns_d3$clock = clock;
        ns_d4$clock = clock;
        nbeam_d1$clock = clock;
        nbeam_d2$clock = clock;
        nbeam_d3$clock = clock;
        nbeam_d4$clock = clock;
        nb_d1$clock = clock;
        nb_d2$clock = clock;
        nb_d3$clock = clock;
        nb_d4$clock = clock;
        run_d5$clock = clock;
        ns_d5$clock = clock;
        nbeam_d5$clock = clock;
        nb_d5$clock = clock;
        ny_last$clock = clock;
        b_last$clock = clock;
        nb_left$clock = clock;
        nbeam_left$clock = clock;
        ns_left$clock = clock;
        nb_end$clock = clock;
        nbeam_end$clock = clock;
        ns_end$clock = clock;
        ny_last_zero$clock = clock;
        b_last_zero$clock = clock;
        running$d = running$q;
        ns_c$d = ns_c$q;
        nbeam_c$d = nbeam_c$q;
        nb_c$d = nb_c$q;
        valid_q$d = valid_q$q;
        ns_q$d = ns_q$q;
        nbeam_q$d = nbeam_q$q;
        nb_q$d = nb_q$q;
        run_d1$d = run_d1$q;
        run_d2$d = run_d2$q;
        run_d3$d = run_d3$q;
        run_d4$d = run_d4$q;
        ns_d1$d = ns_d1$q;
        ns_d2$d = ns_d2$q;
        ns_d3$d = ns_d3$q;
        ns_d4$d = ns_d4$q;
        nbeam_d1$d = nbeam_d1$q;
        nbeam_d2$d = nbeam_d2$q;
        nbeam_d3$d = nbeam_d3$q;
        nbeam_d4$d = nbeam_d4$q;
        nb_d1$d = nb_d1$q;
        nb_d2$d = nb_d2$q;
        nb_d3$d = nb_d3$q;
        nb_d4$d = nb_d4$q;
        run_d5$d = run_d5$q;
        ns_d5$d = ns_d5$q;
        nbeam_d5$d = nbeam_d5$q;
        nb_d5$d = nb_d5$q;
        ny_last$d = ny_last$q;
        b_last$d = b_last$q;
        nb_left$d = nb_left$q;
        nbeam_left$d = nbeam_left$q;
        ns_left$d = ns_left$q;
        nb_end$d = nb_end$q;
        nbeam_end$d = nbeam_end$q;
        ns_end$d = ns_end$q;
        ny_last_zero$d = ny_last_zero$q;
        b_last_zero$d = b_last_zero$q;
        lead$clock = clock;
        lead$reset = reset;
        lead$running = running$q;
        lead$n_s = ns_c$q;
        lead$n_beam = nbeam_c$q;
        lead$n_b = nb_c$q;
        e_run = running$q;
        e_ns = ns_c$q;
        e_nbeam = nbeam_c$q;
        e_nb = nb_c$q;
        if (perspective) begin
            e_run = lead$running_out;
            e_ns = lead$n_s_out;
            e_nbeam = lead$n_beam_out;
            e_nb = lead$n_b_out;
        end
        run_d1$d = e_run;
        ns_d1$d = e_ns;
        nbeam_d1$d = e_nbeam;
        nb_d1$d = e_nb;
        run_d2$d = run_d1$q;
        ns_d2$d = ns_d1$q;
        nbeam_d2$d = nbeam_d1$q;
        nb_d2$d = nb_d1$q;
        run_d3$d = run_d2$q;
        ns_d3$d = ns_d2$q;
        nbeam_d3$d = nbeam_d2$q;
        nb_d3$d = nb_d2$q;
        run_d4$d = run_d3$q;
        ns_d4$d = ns_d3$q;
        nbeam_d4$d = nbeam_d3$q;
        nb_d4$d = nb_d3$q;
        run_d5$d = run_d4$q;
        ns_d5$d = ns_d4$q;
        nbeam_d5$d = nbeam_d4$q;
        nb_d5$d = nb_d4$q;
        z0 = slices[('h20)+:(16)];
        z1 = slices[('h30)+:(16)];
        ny_m1 = dims[('h10)+:(16)] - 'h1;
        b_m1 = beats[('h20)+:(16)] - 'h1;
        ny_last$d = ny_m1;
        b_last$d = b_m1;
        ny_last_zero$d = ny_m1 == 'h0;
        b_last_zero$d = b_m1 == 'h0;
        lanes$0$clock = clock;
        lanes$0$dims = dims;
        lanes$0$slices = slices;
        lanes$0$axes = axes;
        lanes$0$address_reg = address_reg;
        lanes$0$dx = dx;
        lanes$0$dy = dy;
        lanes$0$eye_x = eye_x;
        lanes$0$eye_y = eye_y;
        lanes$0$eye_z = eye_z;
        lanes$0$d_n_s = ns_c$q;
        lanes$0$d_n_beam = nbeam_c$q;
        lanes$0$d_n_b = nb_c$q;
        lanes$0$a_n_s = e_ns;
        lanes$0$a_n_beam = e_nbeam;
        lanes$0$a_n_b = e_nb;
        lanes$0$c_n_s = ns_d4$q;
        lanes$0$c_n_beam = nbeam_d4$q;
        lanes$0$c_n_b = nb_d4$q;
        lanes$0$n_s = ns_d5$q;
        lanes$0$n_beam = nbeam_d5$q;
        lanes$0$load_enable = load_enable;
        lanes$0$load_module = load_module;
        lanes$0$load_address = load_address;
        lanes$0$load_data = load_data;
        value$0 = lanes$0$value;
        x$0 = lanes$0$x;
        z$0 = lanes$0$z;
        address$0 = lanes$0$address;
        y$0 = lanes$0$y;
        pad$0 = lanes$0$pad;
        sr$0 = lanes$0$sr;
        er$0 = lanes$0$er;
        base_x$0 = lanes$0$base_x;
        base_y$0 = lanes$0$base_y;
        face$0 = lanes$0$face;
        at_edge$0 = lanes$0$at_edge;
        invalid$0 = lanes$0$invalid;
        halo$0 = lanes$0$halo;
        ext_addr$0 = lanes$0$ext_addr;
        lanes$0$ext_data = ext_data$0;
        dx_neg$0 = lanes$0$dx_neg;
        dx_mag$0 = lanes$0$dx_mag;
        dy_neg$0 = lanes$0$dy_neg;
        dy_mag$0 = lanes$0$dy_mag;
        lanes$1$clock = clock;
        lanes$1$dims = dims;
        lanes$1$slices = slices;
        lanes$1$axes = axes;
        lanes$1$address_reg = address_reg;
        lanes$1$dx = dx;
        lanes$1$dy = dy;
        lanes$1$eye_x = eye_x;
        lanes$1$eye_y = eye_y;
        lanes$1$eye_z = eye_z;
        lanes$1$d_n_s = ns_c$q;
        lanes$1$d_n_beam = nbeam_c$q;
        lanes$1$d_n_b = nb_c$q;
        lanes$1$a_n_s = e_ns;
        lanes$1$a_n_beam = e_nbeam;
        lanes$1$a_n_b = e_nb;
        lanes$1$c_n_s = ns_d4$q;
        lanes$1$c_n_beam = nbeam_d4$q;
        lanes$1$c_n_b = nb_d4$q;
        lanes$1$n_s = ns_d5$q;
        lanes$1$n_beam = nbeam_d5$q;
        lanes$1$load_enable = load_enable;
        lanes$1$load_module = load_module;
        lanes$1$load_address = load_address;
        lanes$1$load_data = load_data;
        value$1 = lanes$1$value;
        x$1 = lanes$1$x;
        z$1 = lanes$1$z;
        address$1 = lanes$1$address;
        y$1 = lanes$1$y;
        pad$1 = lanes$1$pad;
        sr$1 = lanes$1$sr;
        er$1 = lanes$1$er;
        base_x$1 = lanes$1$base_x;
        base_y$1 = lanes$1$base_y;
        face$1 = lanes$1$face;
        at_edge$1 = lanes$1$at_edge;
        invalid$1 = lanes$1$invalid;
        halo$1 = lanes$1$halo;
        ext_addr$1 = lanes$1$ext_addr;
        lanes$1$ext_data = ext_data$1;
        dx_neg$1 = lanes$1$dx_neg;
        dx_mag$1 = lanes$1$dx_mag;
        dy_neg$1 = lanes$1$dy_neg;
        dy_mag$1 = lanes$1$dy_mag;
        if (start & ~running$q) begin
            running$d = 1'b1;
            ns_c$d = z0;
            nbeam_c$d = 'h0;
            nb_c$d = 'h0;
            nb_left$d = b_m1;
            nbeam_left$d = ny_m1;
            ns_left$d = z1 - z0;
            nb_end$d = b_m1 == 'h0;
            nbeam_end$d = ny_m1 == 'h0;
            ns_end$d = z1 == z0;
        end
        if (running$q) begin
            if (~nb_end$q) begin
                nb_c$d = nb_c$q + 'h1;
                nb_left$d = nb_left$q - 'h1;
                nb_end$d = nb_left$q == 'h1;
            end
            else begin
                nb_c$d = 'h0;
                nb_left$d = b_last$q;
                nb_end$d = b_last_zero$q;
                if (~nbeam_end$q) begin
                    nbeam_c$d = nbeam_c$q + 'h1;
                    nbeam_left$d = nbeam_left$q - 'h1;
                    nbeam_end$d = nbeam_left$q == 'h1;
                end
                else begin
                    nbeam_c$d = 'h0;
                    nbeam_left$d = ny_last$q;
                    nbeam_end$d = ny_last_zero$q;
                    if (~ns_end$q) begin
                        ns_c$d = ns_c$q + 'h1;
                        ns_left$d = ns_left$q - 'h1;
                        ns_end$d = ns_left$q == 'h1;
                    end
                    else begin
                        running$d = 1'b0;
                    end
                end
            end
        end
        if (reset) begin
            running$d = 1'b0;
        end
        valid_q$d = run_d5$q;
        ns_q$d = ns_d5$q;
        nbeam_q$d = nbeam_d5$q;
        nb_q$d = nb_d5$q;
        busy_pass = running$q;
        if (perspective) begin
            busy_pass = lead$busy;
        end
        valid = valid_q$q;
        n_s = ns_q$q;
        n_beam = nbeam_q$q;
        n_b = nb_q$q;
        bs = nb_q$q == 'h0;
        busy = busy_pass;
    end
    
endmodule // top$cfb
module top$cfb$b_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$b_last
module top$cfb$b_last_zero(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$b_last_zero
module top$cfb$lanes$0(clock,dims,slices,axes,address_reg,dx,dy,eye_x,eye_y,eye_z,d_n_s,d_n_beam,d_n_b,a_n_s,a_n_beam,a_n_b,c_n_s,c_n_beam,c_n_b,n_s,n_beam,load_enable,load_module,load_address,load_data,ext_addr,ext_data,value,x,y,z,address,pad,sr,er,at_edge,face,base_x,base_y,halo,dx_neg,dx_mag,dy_neg,dy_mag,invalid);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] dims;
    input wire  [63:0] slices;
    input wire  [63:0] axes;
    input wire  [63:0] address_reg;
    input wire  [63:0] dx;
    input wire  [63:0] dy;
    input wire  [63:0] eye_x;
    input wire  [63:0] eye_y;
    input wire  [63:0] eye_z;
    input wire  [15:0] d_n_s;
    input wire  [15:0] d_n_beam;
    input wire  [15:0] d_n_b;
    input wire  [15:0] a_n_s;
    input wire  [15:0] a_n_beam;
    input wire  [15:0] a_n_b;
    input wire  [15:0] c_n_s;
    input wire  [15:0] c_n_beam;
    input wire  [15:0] c_n_b;
    input wire  [15:0] n_s;
    input wire  [15:0] n_beam;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [15:0] load_address;
    input wire  [15:0] load_data;
    output reg  [31:0] ext_addr;
    input wire  [15:0] ext_data;
    output reg  [15:0] value;
    output reg  [15:0] x;
    output reg  [15:0] y;
    output reg  [15:0] z;
    output reg  [31:0] address;
    output reg  pad;
    output reg  sr;
    output reg  er;
    output reg  at_edge;
    output reg  [2:0] face;
    output reg  [15:0] base_x;
    output reg  [15:0] base_y;
    output reg  halo;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    output reg  invalid;
    
    // Constant declarations
    localparam  lane = 16'h0;
    localparam  p_mask = 16'h1;
    localparam  p_shift = 8'h1;
    localparam  perspective = 1'b1;
    localparam  external = 1'b0;
    
    // Stub signals
    reg  [15:0] memory$read_address;
    reg  memory$read_clock;
    wire  [15:0] memory$read_data;
    reg  [15:0] memory$write_address;
    reg  memory$write_clock;
    reg  [15:0] memory$write_data;
    reg  memory$write_enable;
    reg  [47:0] view_dims$d;
    wire  [47:0] view_dims$q;
    reg  view_dims$clock;
    reg  [31:0] view_slices$d;
    wire  [31:0] view_slices$q;
    reg  view_slices$clock;
    reg  [5:0] view_axes$d;
    wire  [5:0] view_axes$q;
    reg  view_axes$clock;
    reg  [32:0] view_dx$d;
    wire  [32:0] view_dx$q;
    reg  view_dx$clock;
    reg  [32:0] view_dy$d;
    wire  [32:0] view_dy$q;
    reg  view_dy$clock;
    reg  [15:0] nx$d;
    wire  [15:0] nx$q;
    reg  nx$clock;
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [15:0] nz_last$d;
    wire  [15:0] nz_last$q;
    reg  nz_last$clock;
    reg  [15:0] border$d;
    wire  [15:0] border$q;
    reg  border$clock;
    reg  [15:0] b_u$d;
    wire  [15:0] b_u$q;
    reg  b_u$clock;
    reg  [15:0] slab_lo$d;
    wire  [15:0] slab_lo$q;
    reg  slab_lo$clock;
    reg  [15:0] slab_hi$d;
    wire  [15:0] slab_hi$q;
    reg  slab_hi$clock;
    reg  par_dxn$d;
    wire  par_dxn$q;
    reg  par_dxn$clock;
    reg  [15:0] par_dxm$d;
    wire  [15:0] par_dxm$q;
    reg  par_dxm$clock;
    reg  par_dx_pos$d;
    wire  par_dx_pos$q;
    reg  par_dx_pos$clock;
    reg  par_dyn$d;
    wire  par_dyn$q;
    reg  par_dyn$clock;
    reg  [15:0] par_dym$d;
    wire  [15:0] par_dym$q;
    reg  par_dym$clock;
    reg  par_dy_pos$d;
    wire  par_dy_pos$q;
    reg  par_dy_pos$clock;
    reg  div$clock;
    reg  [15:0] div$n_s;
    reg  [15:0] div$n_beam;
    reg  [15:0] div$n_b;
    reg  [63:0] div$eye_x;
    reg  [63:0] div$eye_y;
    reg  [63:0] div$eye_z;
    wire  div$dx_neg;
    wire  [15:0] div$dx_mag;
    wire  div$dx_pos;
    wire  div$dy_neg;
    wire  [15:0] div$dy_mag;
    wire  div$dy_pos;
    wire  div$invalid;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  inval_q$d;
    wire  inval_q$q;
    reg  inval_q$clock;
    reg  halo_q$d;
    wire  halo_q$q;
    reg  halo_q$clock;
    reg  [15:0] xc_r$d;
    wire  [15:0] xc_r$q;
    reg  xc_r$clock;
    reg  pad_r$d;
    wire  pad_r$q;
    reg  pad_r$clock;
    reg  [15:0] a_u$d;
    wire  [15:0] a_u$q;
    reg  a_u$clock;
    reg  [15:0] a_v$d;
    wire  [15:0] a_v$q;
    reg  a_v$clock;
    reg  [15:0] a_w$d;
    wire  [15:0] a_w$q;
    reg  a_w$clock;
    reg  a_pad$d;
    wire  a_pad$q;
    reg  a_pad$clock;
    reg  [31:0] m_u$d;
    wire  [31:0] m_u$q;
    reg  m_u$clock;
    reg  m_v$clock;
    reg  [15:0] m_v$a;
    reg  [15:0] m_v$b;
    wire  [31:0] m_v$p;
    reg  m_w_lo$clock;
    reg  [15:0] m_w_lo$a;
    reg  [15:0] m_w_lo$b;
    wire  [31:0] m_w_lo$p;
    reg  m_w_hi$clock;
    reg  [15:0] m_w_hi$a;
    reg  [15:0] m_w_hi$b;
    wire  [31:0] m_w_hi$p;
    reg  m_pad$d;
    wire  m_pad$q;
    reg  m_pad$clock;
    reg  [31:0] addr$d;
    wire  [31:0] addr$q;
    reg  addr$clock;
    reg  x_last_r$d;
    wire  x_last_r$q;
    reg  x_last_r$clock;
    reg  x_first_r$d;
    wire  x_first_r$q;
    reg  x_first_r$clock;
    reg  y_last_r$d;
    wire  y_last_r$q;
    reg  y_last_r$clock;
    reg  y_first_r$d;
    wire  y_first_r$q;
    reg  y_first_r$clock;
    reg  s_last_r$d;
    wire  s_last_r$q;
    reg  s_last_r$clock;
    reg  [15:0] bx_at_r$d;
    wire  [15:0] bx_at_r$q;
    reg  bx_at_r$clock;
    reg  [15:0] bx_far_r$d;
    wire  [15:0] bx_far_r$q;
    reg  bx_far_r$clock;
    reg  [15:0] b_near_r$d;
    wire  [15:0] b_near_r$q;
    reg  b_near_r$clock;
    reg  [15:0] by_at_r$d;
    wire  [15:0] by_at_r$q;
    reg  by_at_r$clock;
    reg  [15:0] by_far_r$d;
    wire  [15:0] by_far_r$q;
    reg  by_far_r$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  [15:0] z_q$d;
    wire  [15:0] z_q$q;
    reg  z_q$clock;
    reg  [31:0] addr_q$d;
    wire  [31:0] addr_q$q;
    reg  addr_q$clock;
    reg  [31:0] addr_q2$d;
    wire  [31:0] addr_q2$q;
    reg  addr_q2$clock;
    reg  [31:0] addr_q3$d;
    wire  [31:0] addr_q3$q;
    reg  addr_q3$clock;
    reg  pad_q$d;
    wire  pad_q$q;
    reg  pad_q$clock;
    reg  [15:0] ext_q$d;
    wire  [15:0] ext_q$q;
    reg  ext_q$clock;
    reg  [15:0] ext_q2$d;
    wire  [15:0] ext_q2$q;
    reg  ext_q2$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  edge_q$d;
    wire  edge_q$q;
    reg  edge_q$clock;
    reg  [2:0] face_q$d;
    wire  [2:0] face_q$q;
    reg  face_q$clock;
    reg  [15:0] bx_q$d;
    wire  [15:0] bx_q$q;
    reg  bx_q$clock;
    reg  [15:0] by_q$d;
    wire  [15:0] by_q$q;
    reg  by_q$clock;
    
    // Local signals
    reg  [15:0] z0;
    reg  [15:0] z1;
    reg  [1:0] u_from;
    reg  [1:0] v_from;
    reg  [1:0] w_from;
    reg  [15:0] dx_abs;
    reg  [15:0] dy_abs;
    reg  dxn;
    reg  [15:0] dxm;
    reg  dyn_;
    reg  [15:0] dym;
    reg  inval;
    reg  dx_pos;
    reg  dx_neg_nz;
    reg  dy_pos;
    reg  dy_neg_nz;
    reg  [15:0] c_xc;
    reg  [15:0] xc;
    reg  [15:0] a_xc;
    reg  is_pad;
    reg  [2:0] face_c;
    reg  [15:0] c_depth;
    reg  [15:0] bx;
    reg  [15:0] by;
    
    // Sub module instances
    top$cfb$lanes$0$memory memory(
        .read_address(memory$read_address),
        .read_clock(memory$read_clock),
        .read_data(memory$read_data),
        .write_address(memory$write_address),
        .write_clock(memory$write_clock),
        .write_data(memory$write_data),
        .write_enable(memory$write_enable)
    );
    top$cfb$lanes$0$view_dims view_dims(
        .d(view_dims$d),
        .q(view_dims$q),
        .clock(view_dims$clock)
    );
    top$cfb$lanes$0$view_slices view_slices(
        .d(view_slices$d),
        .q(view_slices$q),
        .clock(view_slices$clock)
    );
    top$cfb$lanes$0$view_axes view_axes(
        .d(view_axes$d),
        .q(view_axes$q),
        .clock(view_axes$clock)
    );
    top$cfb$lanes$0$view_dx view_dx(
        .d(view_dx$d),
        .q(view_dx$q),
        .clock(view_dx$clock)
    );
    top$cfb$lanes$0$view_dy view_dy(
        .d(view_dy$d),
        .q(view_dy$q),
        .clock(view_dy$clock)
    );
    top$cfb$lanes$0$nx nx(
        .d(nx$d),
        .q(nx$q),
        .clock(nx$clock)
    );
    top$cfb$lanes$0$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$cfb$lanes$0$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$cfb$lanes$0$nz_last nz_last(
        .d(nz_last$d),
        .q(nz_last$q),
        .clock(nz_last$clock)
    );
    top$cfb$lanes$0$border border(
        .d(border$d),
        .q(border$q),
        .clock(border$clock)
    );
    top$cfb$lanes$0$b_u b_u(
        .d(b_u$d),
        .q(b_u$q),
        .clock(b_u$clock)
    );
    top$cfb$lanes$0$slab_lo slab_lo(
        .d(slab_lo$d),
        .q(slab_lo$q),
        .clock(slab_lo$clock)
    );
    top$cfb$lanes$0$slab_hi slab_hi(
        .d(slab_hi$d),
        .q(slab_hi$q),
        .clock(slab_hi$clock)
    );
    top$cfb$lanes$0$par_dxn par_dxn(
        .d(par_dxn$d),
        .q(par_dxn$q),
        .clock(par_dxn$clock)
    );
    top$cfb$lanes$0$par_dxm par_dxm(
        .d(par_dxm$d),
        .q(par_dxm$q),
        .clock(par_dxm$clock)
    );
    top$cfb$lanes$0$par_dx_pos par_dx_pos(
        .d(par_dx_pos$d),
        .q(par_dx_pos$q),
        .clock(par_dx_pos$clock)
    );
    top$cfb$lanes$0$par_dyn par_dyn(
        .d(par_dyn$d),
        .q(par_dyn$q),
        .clock(par_dyn$clock)
    );
    top$cfb$lanes$0$par_dym par_dym(
        .d(par_dym$d),
        .q(par_dym$q),
        .clock(par_dym$clock)
    );
    top$cfb$lanes$0$par_dy_pos par_dy_pos(
        .d(par_dy_pos$d),
        .q(par_dy_pos$q),
        .clock(par_dy_pos$clock)
    );
    top$cfb$lanes$0$div div(
        .clock(div$clock),
        .n_s(div$n_s),
        .n_beam(div$n_beam),
        .n_b(div$n_b),
        .eye_x(div$eye_x),
        .eye_y(div$eye_y),
        .eye_z(div$eye_z),
        .dx_neg(div$dx_neg),
        .dx_mag(div$dx_mag),
        .dx_pos(div$dx_pos),
        .dy_neg(div$dy_neg),
        .dy_mag(div$dy_mag),
        .dy_pos(div$dy_pos),
        .invalid(div$invalid)
    );
    top$cfb$lanes$0$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$cfb$lanes$0$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$cfb$lanes$0$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$cfb$lanes$0$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$cfb$lanes$0$inval_q inval_q(
        .d(inval_q$d),
        .q(inval_q$q),
        .clock(inval_q$clock)
    );
    top$cfb$lanes$0$halo_q halo_q(
        .d(halo_q$d),
        .q(halo_q$q),
        .clock(halo_q$clock)
    );
    top$cfb$lanes$0$xc_r xc_r(
        .d(xc_r$d),
        .q(xc_r$q),
        .clock(xc_r$clock)
    );
    top$cfb$lanes$0$pad_r pad_r(
        .d(pad_r$d),
        .q(pad_r$q),
        .clock(pad_r$clock)
    );
    top$cfb$lanes$0$a_u a_u(
        .d(a_u$d),
        .q(a_u$q),
        .clock(a_u$clock)
    );
    top$cfb$lanes$0$a_v a_v(
        .d(a_v$d),
        .q(a_v$q),
        .clock(a_v$clock)
    );
    top$cfb$lanes$0$a_w a_w(
        .d(a_w$d),
        .q(a_w$q),
        .clock(a_w$clock)
    );
    top$cfb$lanes$0$a_pad a_pad(
        .d(a_pad$d),
        .q(a_pad$q),
        .clock(a_pad$clock)
    );
    top$cfb$lanes$0$m_u m_u(
        .d(m_u$d),
        .q(m_u$q),
        .clock(m_u$clock)
    );
    top$cfb$lanes$0$m_v m_v(
        .clock(m_v$clock),
        .a(m_v$a),
        .b(m_v$b),
        .p(m_v$p)
    );
    top$cfb$lanes$0$m_w_lo m_w_lo(
        .clock(m_w_lo$clock),
        .a(m_w_lo$a),
        .b(m_w_lo$b),
        .p(m_w_lo$p)
    );
    top$cfb$lanes$0$m_w_hi m_w_hi(
        .clock(m_w_hi$clock),
        .a(m_w_hi$a),
        .b(m_w_hi$b),
        .p(m_w_hi$p)
    );
    top$cfb$lanes$0$m_pad m_pad(
        .d(m_pad$d),
        .q(m_pad$q),
        .clock(m_pad$clock)
    );
    top$cfb$lanes$0$addr addr(
        .d(addr$d),
        .q(addr$q),
        .clock(addr$clock)
    );
    top$cfb$lanes$0$x_last_r x_last_r(
        .d(x_last_r$d),
        .q(x_last_r$q),
        .clock(x_last_r$clock)
    );
    top$cfb$lanes$0$x_first_r x_first_r(
        .d(x_first_r$d),
        .q(x_first_r$q),
        .clock(x_first_r$clock)
    );
    top$cfb$lanes$0$y_last_r y_last_r(
        .d(y_last_r$d),
        .q(y_last_r$q),
        .clock(y_last_r$clock)
    );
    top$cfb$lanes$0$y_first_r y_first_r(
        .d(y_first_r$d),
        .q(y_first_r$q),
        .clock(y_first_r$clock)
    );
    top$cfb$lanes$0$s_last_r s_last_r(
        .d(s_last_r$d),
        .q(s_last_r$q),
        .clock(s_last_r$clock)
    );
    top$cfb$lanes$0$bx_at_r bx_at_r(
        .d(bx_at_r$d),
        .q(bx_at_r$q),
        .clock(bx_at_r$clock)
    );
    top$cfb$lanes$0$bx_far_r bx_far_r(
        .d(bx_far_r$d),
        .q(bx_far_r$q),
        .clock(bx_far_r$clock)
    );
    top$cfb$lanes$0$b_near_r b_near_r(
        .d(b_near_r$d),
        .q(b_near_r$q),
        .clock(b_near_r$clock)
    );
    top$cfb$lanes$0$by_at_r by_at_r(
        .d(by_at_r$d),
        .q(by_at_r$q),
        .clock(by_at_r$clock)
    );
    top$cfb$lanes$0$by_far_r by_far_r(
        .d(by_far_r$d),
        .q(by_far_r$q),
        .clock(by_far_r$clock)
    );
    top$cfb$lanes$0$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$cfb$lanes$0$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$cfb$lanes$0$z_q z_q(
        .d(z_q$d),
        .q(z_q$q),
        .clock(z_q$clock)
    );
    top$cfb$lanes$0$addr_q addr_q(
        .d(addr_q$d),
        .q(addr_q$q),
        .clock(addr_q$clock)
    );
    top$cfb$lanes$0$addr_q2 addr_q2(
        .d(addr_q2$d),
        .q(addr_q2$q),
        .clock(addr_q2$clock)
    );
    top$cfb$lanes$0$addr_q3 addr_q3(
        .d(addr_q3$d),
        .q(addr_q3$q),
        .clock(addr_q3$clock)
    );
    top$cfb$lanes$0$pad_q pad_q(
        .d(pad_q$d),
        .q(pad_q$q),
        .clock(pad_q$clock)
    );
    top$cfb$lanes$0$ext_q ext_q(
        .d(ext_q$d),
        .q(ext_q$q),
        .clock(ext_q$clock)
    );
    top$cfb$lanes$0$ext_q2 ext_q2(
        .d(ext_q2$d),
        .q(ext_q2$q),
        .clock(ext_q2$clock)
    );
    top$cfb$lanes$0$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$cfb$lanes$0$edge_q edge_q(
        .d(edge_q$d),
        .q(edge_q$q),
        .clock(edge_q$clock)
    );
    top$cfb$lanes$0$face_q face_q(
        .d(face_q$d),
        .q(face_q$q),
        .clock(face_q$clock)
    );
    top$cfb$lanes$0$bx_q bx_q(
        .d(bx_q$d),
        .q(bx_q$q),
        .clock(bx_q$clock)
    );
    top$cfb$lanes$0$by_q by_q(
        .d(by_q$d),
        .q(by_q$q),
        .clock(by_q$clock)
    );
    
    // Update code
    reg  [15:0] value_pass;
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        z_q$clock = clock;
        addr_q$clock = clock;
        addr_q2$clock = clock;
        addr_q3$clock = clock;
        pad_q$clock = clock;
        ext_q$clock = clock;
        ext_q2$clock = clock;
        sr_q$clock = clock;
        edge_q$clock = clock;
        face_q$clock = clock;
        bx_q$clock = clock;
        by_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        inval_q$clock = clock;
        halo_q$clock = clock;
        a_u$clock = clock;
        a_v$clock = clock;
        a_w$clock = clock;
        a_pad$clock = clock;
        m_u$clock = clock;
        m_pad$clock = clock;
        addr$clock = clock;
        xc_r$clock = clock;
        pad_r$clock = clock;
        x_last_r$clock = clock;
        x_first_r$clock = clock;
        y_last_r$clock = clock;
        y_first_r$clock = clock;
        s_last_r$clock = clock;
        bx_at_r$clock = clock;
        bx_far_r$clock = clock;
        b_near_r$clock = clock;
        by_at_r$clock = clock;
        by_far_r$clock = clock;
        nx$clock = clock;
        b_u$clock = clock;
        slab_lo$clock = clock;
        slab_hi$clock = clock;
        view_dims$clock = clock;
        view_slices$clock = clock;
        view_axes$clock = clock;
        view_dx$clock = clock;
        view_dy$clock = clock;
        nx_last$clock = clock;
        ny_last$clock = clock;
        nz_last$clock = clock;
        border$clock = clock;
        par_dxn$clock = clock;
        par_dxm$clock = clock;
        par_dx_pos$clock = clock;
        par_dyn$clock = clock;
        par_dym$clock = clock;
        par_dy_pos$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        z_q$d = z_q$q;
        addr_q$d = addr_q$q;
        addr_q2$d = addr_q2$q;
        addr_q3$d = addr_q3$q;
        pad_q$d = pad_q$q;
        ext_q$d = ext_q$q;
        ext_q2$d = ext_q2$q;
        sr_q$d = sr_q$q;
        edge_q$d = edge_q$q;
        face_q$d = face_q$q;
        bx_q$d = bx_q$q;
        by_q$d = by_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        inval_q$d = inval_q$q;
        halo_q$d = halo_q$q;
        a_u$d = a_u$q;
        a_v$d = a_v$q;
        a_w$d = a_w$q;
        a_pad$d = a_pad$q;
        m_u$d = m_u$q;
        m_pad$d = m_pad$q;
        addr$d = addr$q;
        xc_r$d = xc_r$q;
        pad_r$d = pad_r$q;
        x_last_r$d = x_last_r$q;
        x_first_r$d = x_first_r$q;
        y_last_r$d = y_last_r$q;
        y_first_r$d = y_first_r$q;
        s_last_r$d = s_last_r$q;
        bx_at_r$d = bx_at_r$q;
        bx_far_r$d = bx_far_r$q;
        b_near_r$d = b_near_r$q;
        by_at_r$d = by_at_r$q;
        by_far_r$d = by_far_r$q;
        nx$d = nx$q;
        b_u$d = b_u$q;
        slab_lo$d = slab_lo$q;
        slab_hi$d = slab_hi$q;
        view_dims$d = view_dims$q;
        view_slices$d = view_slices$q;
        view_axes$d = view_axes$q;
        view_dx$d = view_dx$q;
        view_dy$d = view_dy$q;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        nz_last$d = nz_last$q;
        border$d = border$q;
        par_dxn$d = par_dxn$q;
        par_dxm$d = par_dxm$q;
        par_dx_pos$d = par_dx_pos$q;
        par_dyn$d = par_dyn$q;
        par_dym$d = par_dym$q;
        par_dy_pos$d = par_dy_pos$q;
        view_dims$d = dims[('h0)+:(48)];
        view_slices$d = slices[('h0)+:(32)];
        view_axes$d = axes[('h0)+:(6)];
        view_dx$d = 33'(dx[('h0)+:(32)]) | (33'(dx[('h3f)+:(1)]) << 'h20);
        view_dy$d = 33'(dy[('h0)+:(32)]) | (33'(dy[('h3f)+:(1)]) << 'h20);
        nx$d = dims[('h0)+:(16)];
        nx_last$d = view_dims$q[('h0)+:(16)] - 'h1;
        ny_last$d = view_dims$q[('h10)+:(16)] - 'h1;
        nz_last$d = view_dims$q[('h20)+:(16)] - 'h1;
        z0 = view_slices$q[('h0)+:(16)];
        z1 = view_slices$q[('h10)+:(16)];
        border$d = z1 - z0;
        u_from = view_axes$q[('h0)+:(2)];
        v_from = view_axes$q[('h2)+:(2)];
        w_from = view_axes$q[('h4)+:(2)];
        b_u$d = address_reg[('h0)+:(16)];
        slab_lo$d = address_reg[('h10)+:(16)];
        slab_hi$d = address_reg[('h20)+:(16)];
        dx_abs = view_dx$q[('h0)+:(16)];
        if (view_dx$q['h20]) begin
            dx_abs = 'h0 - view_dx$q[('h0)+:(16)];
        end
        dy_abs = view_dy$q[('h0)+:(16)];
        if (view_dy$q['h20]) begin
            dy_abs = 'h0 - view_dy$q[('h0)+:(16)];
        end
        par_dxm$d = dx_abs;
        par_dxn$d = view_dx$q['h20] & (view_dx$q[('h0)+:(32)] != 'h0);
        par_dx_pos$d = ~view_dx$q['h20] & (view_dx$q[('h0)+:(32)] != 'h0);
        par_dym$d = dy_abs;
        par_dyn$d = view_dy$q['h20] & (view_dy$q[('h0)+:(32)] != 'h0);
        par_dy_pos$d = ~view_dy$q['h20] & (view_dy$q[('h0)+:(32)] != 'h0);
        memory$read_clock = clock;
        memory$write_clock = clock;
        memory$write_enable = load_enable & (16'(load_module) == lane);
        memory$write_address = load_address;
        memory$write_data = load_data;
        a_xc = (a_n_b << p_shift) | ((lane - a_n_beam - a_n_s) & p_mask);
        a_pad$d = a_xc >= nx$q;
        a_u$d = a_xc;
        if (u_from == 'h1) begin
            a_u$d = a_n_beam;
        end
        if (u_from == 'h2) begin
            a_u$d = a_n_s;
        end
        a_v$d = a_xc;
        if (v_from == 'h1) begin
            a_v$d = a_n_beam;
        end
        if (v_from == 'h2) begin
            a_v$d = a_n_s;
        end
        a_w$d = a_xc;
        if (w_from == 'h1) begin
            a_w$d = a_n_beam;
        end
        if (w_from == 'h2) begin
            a_w$d = a_n_s;
        end
        m_u$d = 32'(a_u$q) >> p_shift;
        m_v$clock = clock;
        m_w_lo$clock = clock;
        m_w_hi$clock = clock;
        m_v$a = a_v$q;
        m_v$b = b_u$q;
        m_w_lo$a = a_w$q;
        m_w_lo$b = slab_lo$q;
        m_w_hi$a = a_w$q;
        m_w_hi$b = slab_hi$q;
        m_pad$d = a_pad$q;
        addr$d = m_u$q + m_v$p + m_w_lo$p + (m_w_hi$p << 'h10);
        if (m_pad$q) begin
            addr$d = 'h0;
        end
        memory$read_address = 16'(addr$q);
        ext_addr = addr$q;
        c_xc = (c_n_b << p_shift) | ((lane - c_n_beam - c_n_s) & p_mask);
        xc_r$d = c_xc;
        pad_r$d = c_xc >= nx$q;
        xc = xc_r$q;
        is_pad = pad_r$q;
        c_depth = z1 - c_n_s;
        x_last_r$d = c_xc == nx_last$q;
        x_first_r$d = c_xc == 'h0;
        y_last_r$d = c_n_beam == ny_last$q;
        y_first_r$d = c_n_beam == 'h0;
        s_last_r$d = c_n_s == z1;
        bx_at_r$d = border$q + c_xc;
        bx_far_r$d = border$q + c_xc + c_depth;
        b_near_r$d = border$q - c_depth;
        by_at_r$d = border$q + c_n_beam;
        by_far_r$d = border$q + c_n_beam + c_depth;
        div$clock = clock;
        div$n_s = d_n_s;
        div$n_beam = d_n_beam;
        div$n_b = d_n_b;
        div$eye_x = eye_x;
        div$eye_y = eye_y;
        div$eye_z = eye_z;
        dxn = par_dxn$q;
        dxm = par_dxm$q;
        dyn_ = par_dyn$q;
        dym = par_dym$q;
        dx_pos = par_dx_pos$q;
        dx_neg_nz = par_dxn$q;
        dy_pos = par_dy_pos$q;
        dy_neg_nz = par_dyn$q;
        inval = 1'b0;
        if (perspective) begin
            dxn = div$dx_neg;
            dyn_ = div$dy_neg;
            dxm = div$dx_mag;
            dym = div$dy_mag;
            inval = div$invalid;
            dx_pos = div$dx_pos;
            dx_neg_nz = div$dx_neg;
            dy_pos = div$dy_pos;
            dy_neg_nz = div$dy_neg;
        end
        if (is_pad) begin
            dxm = 'h0;
            dym = 'h0;
            dxn = 1'b0;
            dyn_ = 1'b0;
        end
        face_c = 'h0;
        bx = bx_at_r$q;
        by = by_at_r$q;
        if (x_last_r$q & dx_pos) begin
            face_c = 'h2;
            bx = bx_far_r$q;
        end
        else if (x_first_r$q & dx_neg_nz) begin
            face_c = 'h3;
            bx = b_near_r$q;
        end
        else if (y_last_r$q & dy_pos) begin
            face_c = 'h4;
            by = by_far_r$q;
        end
        else if (y_first_r$q & dy_neg_nz) begin
            face_c = 'h5;
            by = b_near_r$q;
        end
        if (s_last_r$q) begin
            face_c = 'h1;
            bx = bx_at_r$q;
            by = by_at_r$q;
        end
        if (is_pad | inval) begin
            face_c = 'h0;
        end
        if (face_c == 'h0) begin
            bx = 'h0;
            by = 'h0;
        end
        x_q$d = xc;
        y_q$d = n_beam;
        z_q$d = n_s;
        addr_q$d = addr$q;
        addr_q2$d = addr_q$q;
        addr_q3$d = addr_q2$q;
        pad_q$d = is_pad;
        sr_q$d = n_s == z0;
        edge_q$d = is_pad | x_first_r$q | y_first_r$q | (n_s == 'h0) | x_last_r$q | y_last_r$q | (n_s == nz_last$q);
        face_q$d = face_c;
        bx_q$d = bx;
        by_q$d = by;
        dxn_q$d = dxn;
        dxm_q$d = dxm;
        dyn_q$d = dyn_;
        dym_q$d = dym;
        inval_q$d = inval | is_pad;
        halo_q$d = (n_s + 'h1 <= z0) | (n_s > z1);
        ext_q$d = ext_data;
        ext_q2$d = ext_q$q;
        value_pass = memory$read_data;
        if (external) begin
            value_pass = ext_q2$q;
        end
        if (pad_q$q) begin
            value_pass = 'h0;
        end
        x = x_q$q;
        y = y_q$q;
        z = z_q$q;
        address = addr_q3$q;
        pad = pad_q$q;
        sr = sr_q$q;
        er = face_q$q != 'h0;
        at_edge = edge_q$q;
        face = face_q$q;
        base_x = bx_q$q;
        base_y = by_q$q;
        dx_neg = dxn_q$q;
        dx_mag = dxm_q$q;
        dy_neg = dyn_q$q;
        dy_mag = dym_q$q;
        invalid = inval_q$q;
        halo = halo_q$q;
        value = value_pass;
    end
    
endmodule // top$cfb$lanes$0
module top$cfb$lanes$0$a_pad(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$a_pad
module top$cfb$lanes$0$a_u(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$a_u
module top$cfb$lanes$0$a_v(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$a_v
module top$cfb$lanes$0$a_w(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$a_w
module top$cfb$lanes$0$addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$addr
module top$cfb$lanes$0$addr_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$addr_q
module top$cfb$lanes$0$addr_q2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$addr_q2
module top$cfb$lanes$0$addr_q3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$addr_q3
module top$cfb$lanes$0$b_near_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$b_near_r
module top$cfb$lanes$0$b_u(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$b_u
module top$cfb$lanes$0$border(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$border
module top$cfb$lanes$0$bx_at_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$bx_at_r
module top$cfb$lanes$0$bx_far_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$bx_far_r
module top$cfb$lanes$0$bx_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$bx_q
module top$cfb$lanes$0$by_at_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$by_at_r
module top$cfb$lanes$0$by_far_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$by_far_r
module top$cfb$lanes$0$by_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$by_q
module top$cfb$lanes$0$dxm_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$dxm_q
module top$cfb$lanes$0$dxn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$dxn_q
module top$cfb$lanes$0$dym_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$dym_q
module top$cfb$lanes$0$dyn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$dyn_q
module top$cfb$lanes$0$edge_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$edge_q
module top$cfb$lanes$0$ext_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$ext_q
module top$cfb$lanes$0$ext_q2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$ext_q2
module top$cfb$lanes$0$face_q(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$face_q
module top$cfb$lanes$0$halo_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$halo_q
module top$cfb$lanes$0$inval_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$inval_q
module top$cfb$lanes$0$m_pad(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$m_pad
module top$cfb$lanes$0$m_u(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$m_u
module top$cfb$lanes$0$m_v(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$0$m_v
module top$cfb$lanes$0$m_w_hi(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$0$m_w_hi
module top$cfb$lanes$0$m_w_lo(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$0$m_w_lo
module top$cfb$lanes$0$memory(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16383:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$cfb$lanes$0$memory
module top$cfb$lanes$0$nx(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$nx
module top$cfb$lanes$0$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$nx_last
module top$cfb$lanes$0$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$ny_last
module top$cfb$lanes$0$nz_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$nz_last
module top$cfb$lanes$0$pad_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$pad_q
module top$cfb$lanes$0$pad_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$pad_r
module top$cfb$lanes$0$par_dx_pos(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dx_pos
module top$cfb$lanes$0$par_dxm(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dxm
module top$cfb$lanes$0$par_dxn(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dxn
module top$cfb$lanes$0$par_dy_pos(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dy_pos
module top$cfb$lanes$0$par_dym(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dym
module top$cfb$lanes$0$par_dyn(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$par_dyn
module top$cfb$lanes$0$s_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$s_last_r
module top$cfb$lanes$0$slab_hi(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$slab_hi
module top$cfb$lanes$0$slab_lo(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$slab_lo
module top$cfb$lanes$0$sr_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$sr_q
module top$cfb$lanes$0$view_axes(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$view_axes
module top$cfb$lanes$0$view_dims(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$view_dims
module top$cfb$lanes$0$view_dx(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$view_dx
module top$cfb$lanes$0$view_dy(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$view_dy
module top$cfb$lanes$0$view_slices(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$0$view_slices
module top$cfb$lanes$0$x_first_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$x_first_r
module top$cfb$lanes$0$x_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$x_last_r
module top$cfb$lanes$0$x_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$x_q
module top$cfb$lanes$0$xc_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$xc_r
module top$cfb$lanes$0$y_first_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$y_first_r
module top$cfb$lanes$0$y_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$y_last_r
module top$cfb$lanes$0$y_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$y_q
module top$cfb$lanes$0$z_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$z_q
module top$cfb$lanes$1(clock,dims,slices,axes,address_reg,dx,dy,eye_x,eye_y,eye_z,d_n_s,d_n_beam,d_n_b,a_n_s,a_n_beam,a_n_b,c_n_s,c_n_beam,c_n_b,n_s,n_beam,load_enable,load_module,load_address,load_data,ext_addr,ext_data,value,x,y,z,address,pad,sr,er,at_edge,face,base_x,base_y,halo,dx_neg,dx_mag,dy_neg,dy_mag,invalid);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] dims;
    input wire  [63:0] slices;
    input wire  [63:0] axes;
    input wire  [63:0] address_reg;
    input wire  [63:0] dx;
    input wire  [63:0] dy;
    input wire  [63:0] eye_x;
    input wire  [63:0] eye_y;
    input wire  [63:0] eye_z;
    input wire  [15:0] d_n_s;
    input wire  [15:0] d_n_beam;
    input wire  [15:0] d_n_b;
    input wire  [15:0] a_n_s;
    input wire  [15:0] a_n_beam;
    input wire  [15:0] a_n_b;
    input wire  [15:0] c_n_s;
    input wire  [15:0] c_n_beam;
    input wire  [15:0] c_n_b;
    input wire  [15:0] n_s;
    input wire  [15:0] n_beam;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [15:0] load_address;
    input wire  [15:0] load_data;
    output reg  [31:0] ext_addr;
    input wire  [15:0] ext_data;
    output reg  [15:0] value;
    output reg  [15:0] x;
    output reg  [15:0] y;
    output reg  [15:0] z;
    output reg  [31:0] address;
    output reg  pad;
    output reg  sr;
    output reg  er;
    output reg  at_edge;
    output reg  [2:0] face;
    output reg  [15:0] base_x;
    output reg  [15:0] base_y;
    output reg  halo;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    output reg  invalid;
    
    // Constant declarations
    localparam  lane = 16'h1;
    localparam  p_mask = 16'h1;
    localparam  p_shift = 8'h1;
    localparam  perspective = 1'b1;
    localparam  external = 1'b0;
    
    // Stub signals
    reg  [15:0] memory$read_address;
    reg  memory$read_clock;
    wire  [15:0] memory$read_data;
    reg  [15:0] memory$write_address;
    reg  memory$write_clock;
    reg  [15:0] memory$write_data;
    reg  memory$write_enable;
    reg  [47:0] view_dims$d;
    wire  [47:0] view_dims$q;
    reg  view_dims$clock;
    reg  [31:0] view_slices$d;
    wire  [31:0] view_slices$q;
    reg  view_slices$clock;
    reg  [5:0] view_axes$d;
    wire  [5:0] view_axes$q;
    reg  view_axes$clock;
    reg  [32:0] view_dx$d;
    wire  [32:0] view_dx$q;
    reg  view_dx$clock;
    reg  [32:0] view_dy$d;
    wire  [32:0] view_dy$q;
    reg  view_dy$clock;
    reg  [15:0] nx$d;
    wire  [15:0] nx$q;
    reg  nx$clock;
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [15:0] nz_last$d;
    wire  [15:0] nz_last$q;
    reg  nz_last$clock;
    reg  [15:0] border$d;
    wire  [15:0] border$q;
    reg  border$clock;
    reg  [15:0] b_u$d;
    wire  [15:0] b_u$q;
    reg  b_u$clock;
    reg  [15:0] slab_lo$d;
    wire  [15:0] slab_lo$q;
    reg  slab_lo$clock;
    reg  [15:0] slab_hi$d;
    wire  [15:0] slab_hi$q;
    reg  slab_hi$clock;
    reg  par_dxn$d;
    wire  par_dxn$q;
    reg  par_dxn$clock;
    reg  [15:0] par_dxm$d;
    wire  [15:0] par_dxm$q;
    reg  par_dxm$clock;
    reg  par_dx_pos$d;
    wire  par_dx_pos$q;
    reg  par_dx_pos$clock;
    reg  par_dyn$d;
    wire  par_dyn$q;
    reg  par_dyn$clock;
    reg  [15:0] par_dym$d;
    wire  [15:0] par_dym$q;
    reg  par_dym$clock;
    reg  par_dy_pos$d;
    wire  par_dy_pos$q;
    reg  par_dy_pos$clock;
    reg  div$clock;
    reg  [15:0] div$n_s;
    reg  [15:0] div$n_beam;
    reg  [15:0] div$n_b;
    reg  [63:0] div$eye_x;
    reg  [63:0] div$eye_y;
    reg  [63:0] div$eye_z;
    wire  div$dx_neg;
    wire  [15:0] div$dx_mag;
    wire  div$dx_pos;
    wire  div$dy_neg;
    wire  [15:0] div$dy_mag;
    wire  div$dy_pos;
    wire  div$invalid;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  inval_q$d;
    wire  inval_q$q;
    reg  inval_q$clock;
    reg  halo_q$d;
    wire  halo_q$q;
    reg  halo_q$clock;
    reg  [15:0] xc_r$d;
    wire  [15:0] xc_r$q;
    reg  xc_r$clock;
    reg  pad_r$d;
    wire  pad_r$q;
    reg  pad_r$clock;
    reg  [15:0] a_u$d;
    wire  [15:0] a_u$q;
    reg  a_u$clock;
    reg  [15:0] a_v$d;
    wire  [15:0] a_v$q;
    reg  a_v$clock;
    reg  [15:0] a_w$d;
    wire  [15:0] a_w$q;
    reg  a_w$clock;
    reg  a_pad$d;
    wire  a_pad$q;
    reg  a_pad$clock;
    reg  [31:0] m_u$d;
    wire  [31:0] m_u$q;
    reg  m_u$clock;
    reg  m_v$clock;
    reg  [15:0] m_v$a;
    reg  [15:0] m_v$b;
    wire  [31:0] m_v$p;
    reg  m_w_lo$clock;
    reg  [15:0] m_w_lo$a;
    reg  [15:0] m_w_lo$b;
    wire  [31:0] m_w_lo$p;
    reg  m_w_hi$clock;
    reg  [15:0] m_w_hi$a;
    reg  [15:0] m_w_hi$b;
    wire  [31:0] m_w_hi$p;
    reg  m_pad$d;
    wire  m_pad$q;
    reg  m_pad$clock;
    reg  [31:0] addr$d;
    wire  [31:0] addr$q;
    reg  addr$clock;
    reg  x_last_r$d;
    wire  x_last_r$q;
    reg  x_last_r$clock;
    reg  x_first_r$d;
    wire  x_first_r$q;
    reg  x_first_r$clock;
    reg  y_last_r$d;
    wire  y_last_r$q;
    reg  y_last_r$clock;
    reg  y_first_r$d;
    wire  y_first_r$q;
    reg  y_first_r$clock;
    reg  s_last_r$d;
    wire  s_last_r$q;
    reg  s_last_r$clock;
    reg  [15:0] bx_at_r$d;
    wire  [15:0] bx_at_r$q;
    reg  bx_at_r$clock;
    reg  [15:0] bx_far_r$d;
    wire  [15:0] bx_far_r$q;
    reg  bx_far_r$clock;
    reg  [15:0] b_near_r$d;
    wire  [15:0] b_near_r$q;
    reg  b_near_r$clock;
    reg  [15:0] by_at_r$d;
    wire  [15:0] by_at_r$q;
    reg  by_at_r$clock;
    reg  [15:0] by_far_r$d;
    wire  [15:0] by_far_r$q;
    reg  by_far_r$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  [15:0] z_q$d;
    wire  [15:0] z_q$q;
    reg  z_q$clock;
    reg  [31:0] addr_q$d;
    wire  [31:0] addr_q$q;
    reg  addr_q$clock;
    reg  [31:0] addr_q2$d;
    wire  [31:0] addr_q2$q;
    reg  addr_q2$clock;
    reg  [31:0] addr_q3$d;
    wire  [31:0] addr_q3$q;
    reg  addr_q3$clock;
    reg  pad_q$d;
    wire  pad_q$q;
    reg  pad_q$clock;
    reg  [15:0] ext_q$d;
    wire  [15:0] ext_q$q;
    reg  ext_q$clock;
    reg  [15:0] ext_q2$d;
    wire  [15:0] ext_q2$q;
    reg  ext_q2$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  edge_q$d;
    wire  edge_q$q;
    reg  edge_q$clock;
    reg  [2:0] face_q$d;
    wire  [2:0] face_q$q;
    reg  face_q$clock;
    reg  [15:0] bx_q$d;
    wire  [15:0] bx_q$q;
    reg  bx_q$clock;
    reg  [15:0] by_q$d;
    wire  [15:0] by_q$q;
    reg  by_q$clock;
    
    // Local signals
    reg  [15:0] z0;
    reg  [15:0] z1;
    reg  [1:0] u_from;
    reg  [1:0] v_from;
    reg  [1:0] w_from;
    reg  [15:0] dx_abs;
    reg  [15:0] dy_abs;
    reg  dxn;
    reg  [15:0] dxm;
    reg  dyn_;
    reg  [15:0] dym;
    reg  inval;
    reg  dx_pos;
    reg  dx_neg_nz;
    reg  dy_pos;
    reg  dy_neg_nz;
    reg  [15:0] c_xc;
    reg  [15:0] xc;
    reg  [15:0] a_xc;
    reg  is_pad;
    reg  [2:0] face_c;
    reg  [15:0] c_depth;
    reg  [15:0] bx;
    reg  [15:0] by;
    
    // Sub module instances
    top$cfb$lanes$1$memory memory(
        .read_address(memory$read_address),
        .read_clock(memory$read_clock),
        .read_data(memory$read_data),
        .write_address(memory$write_address),
        .write_clock(memory$write_clock),
        .write_data(memory$write_data),
        .write_enable(memory$write_enable)
    );
    top$cfb$lanes$1$view_dims view_dims(
        .d(view_dims$d),
        .q(view_dims$q),
        .clock(view_dims$clock)
    );
    top$cfb$lanes$1$view_slices view_slices(
        .d(view_slices$d),
        .q(view_slices$q),
        .clock(view_slices$clock)
    );
    top$cfb$lanes$1$view_axes view_axes(
        .d(view_axes$d),
        .q(view_axes$q),
        .clock(view_axes$clock)
    );
    top$cfb$lanes$1$view_dx view_dx(
        .d(view_dx$d),
        .q(view_dx$q),
        .clock(view_dx$clock)
    );
    top$cfb$lanes$1$view_dy view_dy(
        .d(view_dy$d),
        .q(view_dy$q),
        .clock(view_dy$clock)
    );
    top$cfb$lanes$1$nx nx(
        .d(nx$d),
        .q(nx$q),
        .clock(nx$clock)
    );
    top$cfb$lanes$1$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$cfb$lanes$1$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$cfb$lanes$1$nz_last nz_last(
        .d(nz_last$d),
        .q(nz_last$q),
        .clock(nz_last$clock)
    );
    top$cfb$lanes$1$border border(
        .d(border$d),
        .q(border$q),
        .clock(border$clock)
    );
    top$cfb$lanes$1$b_u b_u(
        .d(b_u$d),
        .q(b_u$q),
        .clock(b_u$clock)
    );
    top$cfb$lanes$1$slab_lo slab_lo(
        .d(slab_lo$d),
        .q(slab_lo$q),
        .clock(slab_lo$clock)
    );
    top$cfb$lanes$1$slab_hi slab_hi(
        .d(slab_hi$d),
        .q(slab_hi$q),
        .clock(slab_hi$clock)
    );
    top$cfb$lanes$1$par_dxn par_dxn(
        .d(par_dxn$d),
        .q(par_dxn$q),
        .clock(par_dxn$clock)
    );
    top$cfb$lanes$1$par_dxm par_dxm(
        .d(par_dxm$d),
        .q(par_dxm$q),
        .clock(par_dxm$clock)
    );
    top$cfb$lanes$1$par_dx_pos par_dx_pos(
        .d(par_dx_pos$d),
        .q(par_dx_pos$q),
        .clock(par_dx_pos$clock)
    );
    top$cfb$lanes$1$par_dyn par_dyn(
        .d(par_dyn$d),
        .q(par_dyn$q),
        .clock(par_dyn$clock)
    );
    top$cfb$lanes$1$par_dym par_dym(
        .d(par_dym$d),
        .q(par_dym$q),
        .clock(par_dym$clock)
    );
    top$cfb$lanes$1$par_dy_pos par_dy_pos(
        .d(par_dy_pos$d),
        .q(par_dy_pos$q),
        .clock(par_dy_pos$clock)
    );
    top$cfb$lanes$1$div div(
        .clock(div$clock),
        .n_s(div$n_s),
        .n_beam(div$n_beam),
        .n_b(div$n_b),
        .eye_x(div$eye_x),
        .eye_y(div$eye_y),
        .eye_z(div$eye_z),
        .dx_neg(div$dx_neg),
        .dx_mag(div$dx_mag),
        .dx_pos(div$dx_pos),
        .dy_neg(div$dy_neg),
        .dy_mag(div$dy_mag),
        .dy_pos(div$dy_pos),
        .invalid(div$invalid)
    );
    top$cfb$lanes$1$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$cfb$lanes$1$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$cfb$lanes$1$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$cfb$lanes$1$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$cfb$lanes$1$inval_q inval_q(
        .d(inval_q$d),
        .q(inval_q$q),
        .clock(inval_q$clock)
    );
    top$cfb$lanes$1$halo_q halo_q(
        .d(halo_q$d),
        .q(halo_q$q),
        .clock(halo_q$clock)
    );
    top$cfb$lanes$1$xc_r xc_r(
        .d(xc_r$d),
        .q(xc_r$q),
        .clock(xc_r$clock)
    );
    top$cfb$lanes$1$pad_r pad_r(
        .d(pad_r$d),
        .q(pad_r$q),
        .clock(pad_r$clock)
    );
    top$cfb$lanes$1$a_u a_u(
        .d(a_u$d),
        .q(a_u$q),
        .clock(a_u$clock)
    );
    top$cfb$lanes$1$a_v a_v(
        .d(a_v$d),
        .q(a_v$q),
        .clock(a_v$clock)
    );
    top$cfb$lanes$1$a_w a_w(
        .d(a_w$d),
        .q(a_w$q),
        .clock(a_w$clock)
    );
    top$cfb$lanes$1$a_pad a_pad(
        .d(a_pad$d),
        .q(a_pad$q),
        .clock(a_pad$clock)
    );
    top$cfb$lanes$1$m_u m_u(
        .d(m_u$d),
        .q(m_u$q),
        .clock(m_u$clock)
    );
    top$cfb$lanes$1$m_v m_v(
        .clock(m_v$clock),
        .a(m_v$a),
        .b(m_v$b),
        .p(m_v$p)
    );
    top$cfb$lanes$1$m_w_lo m_w_lo(
        .clock(m_w_lo$clock),
        .a(m_w_lo$a),
        .b(m_w_lo$b),
        .p(m_w_lo$p)
    );
    top$cfb$lanes$1$m_w_hi m_w_hi(
        .clock(m_w_hi$clock),
        .a(m_w_hi$a),
        .b(m_w_hi$b),
        .p(m_w_hi$p)
    );
    top$cfb$lanes$1$m_pad m_pad(
        .d(m_pad$d),
        .q(m_pad$q),
        .clock(m_pad$clock)
    );
    top$cfb$lanes$1$addr addr(
        .d(addr$d),
        .q(addr$q),
        .clock(addr$clock)
    );
    top$cfb$lanes$1$x_last_r x_last_r(
        .d(x_last_r$d),
        .q(x_last_r$q),
        .clock(x_last_r$clock)
    );
    top$cfb$lanes$1$x_first_r x_first_r(
        .d(x_first_r$d),
        .q(x_first_r$q),
        .clock(x_first_r$clock)
    );
    top$cfb$lanes$1$y_last_r y_last_r(
        .d(y_last_r$d),
        .q(y_last_r$q),
        .clock(y_last_r$clock)
    );
    top$cfb$lanes$1$y_first_r y_first_r(
        .d(y_first_r$d),
        .q(y_first_r$q),
        .clock(y_first_r$clock)
    );
    top$cfb$lanes$1$s_last_r s_last_r(
        .d(s_last_r$d),
        .q(s_last_r$q),
        .clock(s_last_r$clock)
    );
    top$cfb$lanes$1$bx_at_r bx_at_r(
        .d(bx_at_r$d),
        .q(bx_at_r$q),
        .clock(bx_at_r$clock)
    );
    top$cfb$lanes$1$bx_far_r bx_far_r(
        .d(bx_far_r$d),
        .q(bx_far_r$q),
        .clock(bx_far_r$clock)
    );
    top$cfb$lanes$1$b_near_r b_near_r(
        .d(b_near_r$d),
        .q(b_near_r$q),
        .clock(b_near_r$clock)
    );
    top$cfb$lanes$1$by_at_r by_at_r(
        .d(by_at_r$d),
        .q(by_at_r$q),
        .clock(by_at_r$clock)
    );
    top$cfb$lanes$1$by_far_r by_far_r(
        .d(by_far_r$d),
        .q(by_far_r$q),
        .clock(by_far_r$clock)
    );
    top$cfb$lanes$1$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$cfb$lanes$1$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$cfb$lanes$1$z_q z_q(
        .d(z_q$d),
        .q(z_q$q),
        .clock(z_q$clock)
    );
    top$cfb$lanes$1$addr_q addr_q(
        .d(addr_q$d),
        .q(addr_q$q),
        .clock(addr_q$clock)
    );
    top$cfb$lanes$1$addr_q2 addr_q2(
        .d(addr_q2$d),
        .q(addr_q2$q),
        .clock(addr_q2$clock)
    );
    top$cfb$lanes$1$addr_q3 addr_q3(
        .d(addr_q3$d),
        .q(addr_q3$q),
        .clock(addr_q3$clock)
    );
    top$cfb$lanes$1$pad_q pad_q(
        .d(pad_q$d),
        .q(pad_q$q),
        .clock(pad_q$clock)
    );
    top$cfb$lanes$1$ext_q ext_q(
        .d(ext_q$d),
        .q(ext_q$q),
        .clock(ext_q$clock)
    );
    top$cfb$lanes$1$ext_q2 ext_q2(
        .d(ext_q2$d),
        .q(ext_q2$q),
        .clock(ext_q2$clock)
    );
    top$cfb$lanes$1$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$cfb$lanes$1$edge_q edge_q(
        .d(edge_q$d),
        .q(edge_q$q),
        .clock(edge_q$clock)
    );
    top$cfb$lanes$1$face_q face_q(
        .d(face_q$d),
        .q(face_q$q),
        .clock(face_q$clock)
    );
    top$cfb$lanes$1$bx_q bx_q(
        .d(bx_q$d),
        .q(bx_q$q),
        .clock(bx_q$clock)
    );
    top$cfb$lanes$1$by_q by_q(
        .d(by_q$d),
        .q(by_q$q),
        .clock(by_q$clock)
    );
    
    // Update code
    reg  [15:0] value_pass;
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        z_q$clock = clock;
        addr_q$clock = clock;
        addr_q2$clock = clock;
        addr_q3$clock = clock;
        pad_q$clock = clock;
        ext_q$clock = clock;
        ext_q2$clock = clock;
        sr_q$clock = clock;
        edge_q$clock = clock;
        face_q$clock = clock;
        bx_q$clock = clock;
        by_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        inval_q$clock = clock;
        halo_q$clock = clock;
        a_u$clock = clock;
        a_v$clock = clock;
        a_w$clock = clock;
        a_pad$clock = clock;
        m_u$clock = clock;
        m_pad$clock = clock;
        addr$clock = clock;
        xc_r$clock = clock;
        pad_r$clock = clock;
        x_last_r$clock = clock;
        x_first_r$clock = clock;
        y_last_r$clock = clock;
        y_first_r$clock = clock;
        s_last_r$clock = clock;
        bx_at_r$clock = clock;
        bx_far_r$clock = clock;
        b_near_r$clock = clock;
        by_at_r$clock = clock;
        by_far_r$clock = clock;
        nx$clock = clock;
        b_u$clock = clock;
        slab_lo$clock = clock;
        slab_hi$clock = clock;
        view_dims$clock = clock;
        view_slices$clock = clock;
        view_axes$clock = clock;
        view_dx$clock = clock;
        view_dy$clock = clock;
        nx_last$clock = clock;
        ny_last$clock = clock;
        nz_last$clock = clock;
        border$clock = clock;
        par_dxn$clock = clock;
        par_dxm$clock = clock;
        par_dx_pos$clock = clock;
        par_dyn$clock = clock;
        par_dym$clock = clock;
        par_dy_pos$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        z_q$d = z_q$q;
        addr_q$d = addr_q$q;
        addr_q2$d = addr_q2$q;
        addr_q3$d = addr_q3$q;
        pad_q$d = pad_q$q;
        ext_q$d = ext_q$q;
        ext_q2$d = ext_q2$q;
        sr_q$d = sr_q$q;
        edge_q$d = edge_q$q;
        face_q$d = face_q$q;
        bx_q$d = bx_q$q;
        by_q$d = by_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        inval_q$d = inval_q$q;
        halo_q$d = halo_q$q;
        a_u$d = a_u$q;
        a_v$d = a_v$q;
        a_w$d = a_w$q;
        a_pad$d = a_pad$q;
        m_u$d = m_u$q;
        m_pad$d = m_pad$q;
        addr$d = addr$q;
        xc_r$d = xc_r$q;
        pad_r$d = pad_r$q;
        x_last_r$d = x_last_r$q;
        x_first_r$d = x_first_r$q;
        y_last_r$d = y_last_r$q;
        y_first_r$d = y_first_r$q;
        s_last_r$d = s_last_r$q;
        bx_at_r$d = bx_at_r$q;
        bx_far_r$d = bx_far_r$q;
        b_near_r$d = b_near_r$q;
        by_at_r$d = by_at_r$q;
        by_far_r$d = by_far_r$q;
        nx$d = nx$q;
        b_u$d = b_u$q;
        slab_lo$d = slab_lo$q;
        slab_hi$d = slab_hi$q;
        view_dims$d = view_dims$q;
        view_slices$d = view_slices$q;
        view_axes$d = view_axes$q;
        view_dx$d = view_dx$q;
        view_dy$d = view_dy$q;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        nz_last$d = nz_last$q;
        border$d = border$q;
        par_dxn$d = par_dxn$q;
        par_dxm$d = par_dxm$q;
        par_dx_pos$d = par_dx_pos$q;
        par_dyn$d = par_dyn$q;
        par_dym$d = par_dym$q;
        par_dy_pos$d = par_dy_pos$q;
        view_dims$d = dims[('h0)+:(48)];
        view_slices$d = slices[('h0)+:(32)];
        view_axes$d = axes[('h0)+:(6)];
        view_dx$d = 33'(dx[('h0)+:(32)]) | (33'(dx[('h3f)+:(1)]) << 'h20);
        view_dy$d = 33'(dy[('h0)+:(32)]) | (33'(dy[('h3f)+:(1)]) << 'h20);
        nx$d = dims[('h0)+:(16)];
        nx_last$d = view_dims$q[('h0)+:(16)] - 'h1;
        ny_last$d = view_dims$q[('h10)+:(16)] - 'h1;
        nz_last$d = view_dims$q[('h20)+:(16)] - 'h1;
        z0 = view_slices$q[('h0)+:(16)];
        z1 = view_slices$q[('h10)+:(16)];
        border$d = z1 - z0;
        u_from = view_axes$q[('h0)+:(2)];
        v_from = view_axes$q[('h2)+:(2)];
        w_from = view_axes$q[('h4)+:(2)];
        b_u$d = address_reg[('h0)+:(16)];
        slab_lo$d = address_reg[('h10)+:(16)];
        slab_hi$d = address_reg[('h20)+:(16)];
        dx_abs = view_dx$q[('h0)+:(16)];
        if (view_dx$q['h20]) begin
            dx_abs = 'h0 - view_dx$q[('h0)+:(16)];
        end
        dy_abs = view_dy$q[('h0)+:(16)];
        if (view_dy$q['h20]) begin
            dy_abs = 'h0 - view_dy$q[('h0)+:(16)];
        end
        par_dxm$d = dx_abs;
        par_dxn$d = view_dx$q['h20] & (view_dx$q[('h0)+:(32)] != 'h0);
        par_dx_pos$d = ~view_dx$q['h20] & (view_dx$q[('h0)+:(32)] != 'h0);
        par_dym$d = dy_abs;
        par_dyn$d = view_dy$q['h20] & (view_dy$q[('h0)+:(32)] != 'h0);
        par_dy_pos$d = ~view_dy$q['h20] & (view_dy$q[('h0)+:(32)] != 'h0);
        memory$read_clock = clock;
        memory$write_clock = clock;
        memory$write_enable = load_enable & (16'(load_module) == lane);
        memory$write_address = load_address;
        memory$write_data = load_data;
        a_xc = (a_n_b << p_shift) | ((lane - a_n_beam - a_n_s) & p_mask);
        a_pad$d = a_xc >= nx$q;
        a_u$d = a_xc;
        if (u_from == 'h1) begin
            a_u$d = a_n_beam;
        end
        if (u_from == 'h2) begin
            a_u$d = a_n_s;
        end
        a_v$d = a_xc;
        if (v_from == 'h1) begin
            a_v$d = a_n_beam;
        end
        if (v_from == 'h2) begin
            a_v$d = a_n_s;
        end
        a_w$d = a_xc;
        if (w_from == 'h1) begin
            a_w$d = a_n_beam;
        end
        if (w_from == 'h2) begin
            a_w$d = a_n_s;
        end
        m_u$d = 32'(a_u$q) >> p_shift;
        m_v$clock = clock;
        m_w_lo$clock = clock;
        m_w_hi$clock = clock;
        m_v$a = a_v$q;
        m_v$b = b_u$q;
        m_w_lo$a = a_w$q;
        m_w_lo$b = slab_lo$q;
        m_w_hi$a = a_w$q;
        m_w_hi$b = slab_hi$q;
        m_pad$d = a_pad$q;
        addr$d = m_u$q + m_v$p + m_w_lo$p + (m_w_hi$p << 'h10);
        if (m_pad$q) begin
            addr$d = 'h0;
        end
        memory$read_address = 16'(addr$q);
        ext_addr = addr$q;
        c_xc = (c_n_b << p_shift) | ((lane - c_n_beam - c_n_s) & p_mask);
        xc_r$d = c_xc;
        pad_r$d = c_xc >= nx$q;
        xc = xc_r$q;
        is_pad = pad_r$q;
        c_depth = z1 - c_n_s;
        x_last_r$d = c_xc == nx_last$q;
        x_first_r$d = c_xc == 'h0;
        y_last_r$d = c_n_beam == ny_last$q;
        y_first_r$d = c_n_beam == 'h0;
        s_last_r$d = c_n_s == z1;
        bx_at_r$d = border$q + c_xc;
        bx_far_r$d = border$q + c_xc + c_depth;
        b_near_r$d = border$q - c_depth;
        by_at_r$d = border$q + c_n_beam;
        by_far_r$d = border$q + c_n_beam + c_depth;
        div$clock = clock;
        div$n_s = d_n_s;
        div$n_beam = d_n_beam;
        div$n_b = d_n_b;
        div$eye_x = eye_x;
        div$eye_y = eye_y;
        div$eye_z = eye_z;
        dxn = par_dxn$q;
        dxm = par_dxm$q;
        dyn_ = par_dyn$q;
        dym = par_dym$q;
        dx_pos = par_dx_pos$q;
        dx_neg_nz = par_dxn$q;
        dy_pos = par_dy_pos$q;
        dy_neg_nz = par_dyn$q;
        inval = 1'b0;
        if (perspective) begin
            dxn = div$dx_neg;
            dyn_ = div$dy_neg;
            dxm = div$dx_mag;
            dym = div$dy_mag;
            inval = div$invalid;
            dx_pos = div$dx_pos;
            dx_neg_nz = div$dx_neg;
            dy_pos = div$dy_pos;
            dy_neg_nz = div$dy_neg;
        end
        if (is_pad) begin
            dxm = 'h0;
            dym = 'h0;
            dxn = 1'b0;
            dyn_ = 1'b0;
        end
        face_c = 'h0;
        bx = bx_at_r$q;
        by = by_at_r$q;
        if (x_last_r$q & dx_pos) begin
            face_c = 'h2;
            bx = bx_far_r$q;
        end
        else if (x_first_r$q & dx_neg_nz) begin
            face_c = 'h3;
            bx = b_near_r$q;
        end
        else if (y_last_r$q & dy_pos) begin
            face_c = 'h4;
            by = by_far_r$q;
        end
        else if (y_first_r$q & dy_neg_nz) begin
            face_c = 'h5;
            by = b_near_r$q;
        end
        if (s_last_r$q) begin
            face_c = 'h1;
            bx = bx_at_r$q;
            by = by_at_r$q;
        end
        if (is_pad | inval) begin
            face_c = 'h0;
        end
        if (face_c == 'h0) begin
            bx = 'h0;
            by = 'h0;
        end
        x_q$d = xc;
        y_q$d = n_beam;
        z_q$d = n_s;
        addr_q$d = addr$q;
        addr_q2$d = addr_q$q;
        addr_q3$d = addr_q2$q;
        pad_q$d = is_pad;
        sr_q$d = n_s == z0;
        edge_q$d = is_pad | x_first_r$q | y_first_r$q | (n_s == 'h0) | x_last_r$q | y_last_r$q | (n_s == nz_last$q);
        face_q$d = face_c;
        bx_q$d = bx;
        by_q$d = by;
        dxn_q$d = dxn;
        dxm_q$d = dxm;
        dyn_q$d = dyn_;
        dym_q$d = dym;
        inval_q$d = inval | is_pad;
        halo_q$d = (n_s + 'h1 <= z0) | (n_s > z1);
        ext_q$d = ext_data;
        ext_q2$d = ext_q$q;
        value_pass = memory$read_data;
        if (external) begin
            value_pass = ext_q2$q;
        end
        if (pad_q$q) begin
            value_pass = 'h0;
        end
        x = x_q$q;
        y = y_q$q;
        z = z_q$q;
        address = addr_q3$q;
        pad = pad_q$q;
        sr = sr_q$q;
        er = face_q$q != 'h0;
        at_edge = edge_q$q;
        face = face_q$q;
        base_x = bx_q$q;
        base_y = by_q$q;
        dx_neg = dxn_q$q;
        dx_mag = dxm_q$q;
        dy_neg = dyn_q$q;
        dy_mag = dym_q$q;
        invalid = inval_q$q;
        halo = halo_q$q;
        value = value_pass;
    end
    
endmodule // top$cfb$lanes$1
module top$cfb$lanes$1$a_pad(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$a_pad
module top$cfb$lanes$1$a_u(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$a_u
module top$cfb$lanes$1$a_v(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$a_v
module top$cfb$lanes$1$a_w(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$a_w
module top$cfb$lanes$1$addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$addr
module top$cfb$lanes$1$addr_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$addr_q
module top$cfb$lanes$1$addr_q2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$addr_q2
module top$cfb$lanes$1$addr_q3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$addr_q3
module top$cfb$lanes$1$b_near_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$b_near_r
module top$cfb$lanes$1$b_u(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$b_u
module top$cfb$lanes$1$border(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$border
module top$cfb$lanes$1$bx_at_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$bx_at_r
module top$cfb$lanes$1$bx_far_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$bx_far_r
module top$cfb$lanes$1$bx_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$bx_q
module top$cfb$lanes$1$by_at_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$by_at_r
module top$cfb$lanes$1$by_far_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$by_far_r
module top$cfb$lanes$1$by_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$by_q
module top$cfb$lanes$1$dxm_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$dxm_q
module top$cfb$lanes$1$dxn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$dxn_q
module top$cfb$lanes$1$dym_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$dym_q
module top$cfb$lanes$1$dyn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$dyn_q
module top$cfb$lanes$1$edge_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$edge_q
module top$cfb$lanes$1$ext_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$ext_q
module top$cfb$lanes$1$ext_q2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$ext_q2
module top$cfb$lanes$1$face_q(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$face_q
module top$cfb$lanes$1$halo_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$halo_q
module top$cfb$lanes$1$inval_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$inval_q
module top$cfb$lanes$1$m_pad(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$m_pad
module top$cfb$lanes$1$m_u(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$m_u
module top$cfb$lanes$1$m_v(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$1$m_v
module top$cfb$lanes$1$m_w_hi(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$1$m_w_hi
module top$cfb$lanes$1$m_w_lo(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$cfb$lanes$1$m_w_lo
module top$cfb$lanes$1$memory(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16383:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16383:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$cfb$lanes$1$memory
module top$cfb$lanes$1$nx(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$nx
module top$cfb$lanes$1$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$nx_last
module top$cfb$lanes$1$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$ny_last
module top$cfb$lanes$1$nz_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$nz_last
module top$cfb$lanes$1$pad_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$pad_q
module top$cfb$lanes$1$pad_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$pad_r
module top$cfb$lanes$1$par_dx_pos(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dx_pos
module top$cfb$lanes$1$par_dxm(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dxm
module top$cfb$lanes$1$par_dxn(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dxn
module top$cfb$lanes$1$par_dy_pos(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dy_pos
module top$cfb$lanes$1$par_dym(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dym
module top$cfb$lanes$1$par_dyn(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$par_dyn
module top$cfb$lanes$1$s_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$s_last_r
module top$cfb$lanes$1$slab_hi(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$slab_hi
module top$cfb$lanes$1$slab_lo(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$slab_lo
module top$cfb$lanes$1$sr_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$sr_q
module top$cfb$lanes$1$view_axes(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$view_axes
module top$cfb$lanes$1$view_dims(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$view_dims
module top$cfb$lanes$1$view_dx(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$view_dx
module top$cfb$lanes$1$view_dy(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$view_dy
module top$cfb$lanes$1$view_slices(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$cfb$lanes$1$view_slices
module top$cfb$lanes$1$x_first_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$x_first_r
module top$cfb$lanes$1$x_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$x_last_r
module top$cfb$lanes$1$x_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$x_q
module top$cfb$lanes$1$xc_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$xc_r
module top$cfb$lanes$1$y_first_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$y_first_r
module top$cfb$lanes$1$y_last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$y_last_r
module top$cfb$lanes$1$y_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$y_q
module top$cfb$lanes$1$z_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$z_q
module top$cfb$nb_c(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_c
module top$cfb$nb_d1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_d1
module top$cfb$nb_d2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_d2
module top$cfb$nb_d3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_d3
module top$cfb$nb_d4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_d4
module top$cfb$nb_d5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_d5
module top$cfb$nb_end(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_end
module top$cfb$nb_left(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_left
module top$cfb$nb_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nb_q
module top$cfb$nbeam_c(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_c
module top$cfb$nbeam_d1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_d1
module top$cfb$nbeam_d2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_d2
module top$cfb$nbeam_d3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_d3
module top$cfb$nbeam_d4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_d4
module top$cfb$nbeam_d5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_d5
module top$cfb$nbeam_end(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_end
module top$cfb$nbeam_left(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_left
module top$cfb$nbeam_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$nbeam_q
module top$cfb$ns_c(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_c
module top$cfb$ns_d1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_d1
module top$cfb$ns_d2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_d2
module top$cfb$ns_d3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_d3
module top$cfb$ns_d4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_d4
module top$cfb$ns_d5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_d5
module top$cfb$ns_end(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_end
module top$cfb$ns_left(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_left
module top$cfb$ns_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ns_q
module top$cfb$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ny_last
module top$cfb$ny_last_zero(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$ny_last_zero
module top$cfb$run_d1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$run_d1
module top$cfb$run_d2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$run_d2
module top$cfb$run_d3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$run_d3
module top$cfb$run_d4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$run_d4
module top$cfb$run_d5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$run_d5
module top$cfb$running(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$running
module top$cfb$valid_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$valid_q
