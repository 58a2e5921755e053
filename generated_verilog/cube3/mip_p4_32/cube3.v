module top$pipeline(clock,start,valid,cur$0,cur$1,cur$2,cur$3,next$0,next$1,next$2,next$3,done,pixel_r,pixel_g,pixel_b,pixel_a,has_sample);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  valid;
    input wire  [15:0] cur$0;
    input wire  [15:0] cur$1;
    input wire  [15:0] cur$2;
    input wire  [15:0] cur$3;
    input wire  [15:0] next$0;
    input wire  [15:0] next$1;
    input wire  [15:0] next$2;
    input wire  [15:0] next$3;
    output reg  done;
    output reg  [31:0] pixel_r;
    output reg  [15:0] pixel_g;
    output reg  [15:0] pixel_b;
    output reg  [15:0] pixel_a;
    output reg  has_sample;
    
    // Constant declarations
    localparam  xray = 1'b0;
    localparam  half = 'h8;
    localparam  frac = 8'h4;
    localparam  row_shift = 8'h0;
    localparam  lane_bit$0 = 16'h1;
    localparam  lane_bit$1 = 16'h2;
    localparam  lane_bit$2 = 16'h4;
    localparam  lane_bit$3 = 16'h8;
    localparam  lane_bit$4 = 16'h10;
    localparam  lane_bit$5 = 16'h20;
    localparam  lane_bit$6 = 16'h40;
    localparam  lane_bit$7 = 16'h80;
    
    // Stub signals
    reg  control$clock;
    reg  control$start;
    reg  control$valid;
    wire  control$first;
    wire  control$unit_valid;
    wire  control$unit_first;
    wire  control$unit_last;
    wire  [15:0] control$wx$0;
    wire  [15:0] control$wx$1;
    wire  [15:0] control$wx$2;
    wire  [15:0] control$wx$3;
    wire  [15:0] control$wy$0;
    wire  [15:0] control$wy$1;
    wire  [15:0] control$wy$2;
    wire  [15:0] control$wy$3;
    wire  [7:0] control$in_volume;
    reg  lanes$clock;
    reg  [15:0] lanes$cur$0;
    reg  [15:0] lanes$cur$1;
    reg  [15:0] lanes$cur$2;
    reg  [15:0] lanes$cur$3;
    reg  [15:0] lanes$next$0;
    reg  [15:0] lanes$next$1;
    reg  [15:0] lanes$next$2;
    reg  [15:0] lanes$next$3;
    reg  lanes$first;
    reg  [15:0] lanes$wx$0;
    reg  [15:0] lanes$wx$1;
    reg  [15:0] lanes$wx$2;
    reg  [15:0] lanes$wx$3;
    reg  [15:0] lanes$wy$0;
    reg  [15:0] lanes$wy$1;
    reg  [15:0] lanes$wy$2;
    reg  [15:0] lanes$wy$3;
    wire  [31:0] lanes$sample$0;
    wire  [31:0] lanes$sample$1;
    wire  [31:0] lanes$sample$2;
    wire  [31:0] lanes$sample$3;
    reg  [15:0] flags_q$0$d;
    wire  [15:0] flags_q$0$q;
    reg  flags_q$0$clock;
    reg  [15:0] flags_q$1$d;
    wire  [15:0] flags_q$1$q;
    reg  flags_q$1$clock;
    reg  [15:0] flags_q$2$d;
    wire  [15:0] flags_q$2$q;
    reg  flags_q$2$clock;
    reg  [15:0] flags_q$3$d;
    wire  [15:0] flags_q$3$q;
    reg  flags_q$3$clock;
    reg  [15:0] flags_q$4$d;
    wire  [15:0] flags_q$4$q;
    reg  flags_q$4$clock;
    reg  [15:0] flags_q$5$d;
    wire  [15:0] flags_q$5$q;
    reg  flags_q$5$clock;
    reg  [15:0] flags_q$6$d;
    wire  [15:0] flags_q$6$q;
    reg  flags_q$6$clock;
    reg  [15:0] flags_q$7$d;
    wire  [15:0] flags_q$7$q;
    reg  flags_q$7$clock;
    reg  [11:0] opacity$0$address;
    wire  [31:0] opacity$0$data;
    reg  [11:0] opacity$1$address;
    wire  [31:0] opacity$1$data;
    reg  [11:0] opacity$2$address;
    wire  [31:0] opacity$2$data;
    reg  [11:0] opacity$3$address;
    wire  [31:0] opacity$3$data;
    reg  [31:0] leaf_q$0$d;
    wire  [31:0] leaf_q$0$q;
    reg  leaf_q$0$clock;
    reg  [31:0] leaf_q$1$d;
    wire  [31:0] leaf_q$1$q;
    reg  leaf_q$1$clock;
    reg  [31:0] leaf_q$2$d;
    wire  [31:0] leaf_q$2$q;
    reg  leaf_q$2$clock;
    reg  [31:0] leaf_q$3$d;
    wire  [31:0] leaf_q$3$q;
    reg  leaf_q$3$clock;
    reg  leaf_valid_q$0$d;
    wire  leaf_valid_q$0$q;
    reg  leaf_valid_q$0$clock;
    reg  leaf_valid_q$1$d;
    wire  leaf_valid_q$1$q;
    reg  leaf_valid_q$1$clock;
    reg  leaf_valid_q$2$d;
    wire  leaf_valid_q$2$q;
    reg  leaf_valid_q$2$clock;
    reg  leaf_valid_q$3$d;
    wire  leaf_valid_q$3$q;
    reg  leaf_valid_q$3$clock;
    reg  rpc$clock;
    reg  [31:0] rpc$leaf_r$0;
    reg  [31:0] rpc$leaf_r$1;
    reg  [31:0] rpc$leaf_r$2;
    reg  [31:0] rpc$leaf_r$3;
    reg  [15:0] rpc$leaf_g$0;
    reg  [15:0] rpc$leaf_g$1;
    reg  [15:0] rpc$leaf_g$2;
    reg  [15:0] rpc$leaf_g$3;
    reg  [15:0] rpc$leaf_b$0;
    reg  [15:0] rpc$leaf_b$1;
    reg  [15:0] rpc$leaf_b$2;
    reg  [15:0] rpc$leaf_b$3;
    reg  [15:0] rpc$leaf_a$0;
    reg  [15:0] rpc$leaf_a$1;
    reg  [15:0] rpc$leaf_a$2;
    reg  [15:0] rpc$leaf_a$3;
    reg  rpc$leaf_valid$0;
    reg  rpc$leaf_valid$1;
    reg  rpc$leaf_valid$2;
    reg  rpc$leaf_valid$3;
    reg  rpc$first;
    reg  rpc$last;
    wire  rpc$done;
    wire  [31:0] rpc$pixel_r;
    wire  [15:0] rpc$pixel_g;
    wire  [15:0] rpc$pixel_b;
    wire  [15:0] rpc$pixel_a;
    wire  rpc$has_sample;
    
    // Local signals
    reg  [31:0] row$0;
    reg  [31:0] row$1;
    reg  [31:0] row$2;
    reg  [31:0] row$3;
    
    // Sub module instances
    top$pipeline$control control(
        .clock(control$clock),
        .start(control$start),
        .valid(control$valid),
        .first(control$first),
        .unit_valid(control$unit_valid),
        .unit_first(control$unit_first),
        .unit_last(control$unit_last),
        .wx$0(control$wx$0),
        .wx$1(control$wx$1),
        .wx$2(control$wx$2),
        .wx$3(control$wx$3),
        .wy$0(control$wy$0),
        .wy$1(control$wy$1),
        .wy$2(control$wy$2),
        .wy$3(control$wy$3),
        .in_volume(control$in_volume)
    );
    top$pipeline$lanes lanes(
        .clock(lanes$clock),
        .cur$0(lanes$cur$0),
        .cur$1(lanes$cur$1),
        .cur$2(lanes$cur$2),
        .cur$3(lanes$cur$3),
        .next$0(lanes$next$0),
        .next$1(lanes$next$1),
        .next$2(lanes$next$2),
        .next$3(lanes$next$3),
        .first(lanes$first),
        .wx$0(lanes$wx$0),
        .wx$1(lanes$wx$1),
        .wx$2(lanes$wx$2),
        .wx$3(lanes$wx$3),
        .wy$0(lanes$wy$0),
        .wy$1(lanes$wy$1),
        .wy$2(lanes$wy$2),
        .wy$3(lanes$wy$3),
        .sample$0(lanes$sample$0),
        .sample$1(lanes$sample$1),
        .sample$2(lanes$sample$2),
        .sample$3(lanes$sample$3)
    );
    top$pipeline$flags_q$0 flags_q$0(
        .d(flags_q$0$d),
        .q(flags_q$0$q),
        .clock(flags_q$0$clock)
    );
    top$pipeline$flags_q$1 flags_q$1(
        .d(flags_q$1$d),
        .q(flags_q$1$q),
        .clock(flags_q$1$clock)
    );
    top$pipeline$flags_q$2 flags_q$2(
        .d(flags_q$2$d),
        .q(flags_q$2$q),
        .clock(flags_q$2$clock)
    );
    top$pipeline$flags_q$3 flags_q$3(
        .d(flags_q$3$d),
        .q(flags_q$3$q),
        .clock(flags_q$3$clock)
    );
    top$pipeline$flags_q$4 flags_q$4(
        .d(flags_q$4$d),
        .q(flags_q$4$q),
        .clock(flags_q$4$clock)
    );
    top$pipeline$flags_q$5 flags_q$5(
        .d(flags_q$5$d),
        .q(flags_q$5$q),
        .clock(flags_q$5$clock)
    );
    top$pipeline$flags_q$6 flags_q$6(
        .d(flags_q$6$d),
        .q(flags_q$6$q),
        .clock(flags_q$6$clock)
    );
    top$pipeline$flags_q$7 flags_q$7(
        .d(flags_q$7$d),
        .q(flags_q$7$q),
        .clock(flags_q$7$clock)
    );
    top$pipeline$opacity$0 opacity$0(
        .address(opacity$0$address),
        .data(opacity$0$data)
    );
    top$pipeline$opacity$1 opacity$1(
        .address(opacity$1$address),
        .data(opacity$1$data)
    );
    top$pipeline$opacity$2 opacity$2(
        .address(opacity$2$address),
        .data(opacity$2$data)
    );
    top$pipeline$opacity$3 opacity$3(
        .address(opacity$3$address),
        .data(opacity$3$data)
    );
    top$pipeline$leaf_q$0 leaf_q$0(
        .d(leaf_q$0$d),
        .q(leaf_q$0$q),
        .clock(leaf_q$0$clock)
    );
    top$pipeline$leaf_q$1 leaf_q$1(
        .d(leaf_q$1$d),
        .q(leaf_q$1$q),
        .clock(leaf_q$1$clock)
    );
    top$pipeline$leaf_q$2 leaf_q$2(
        .d(leaf_q$2$d),
        .q(leaf_q$2$q),
        .clock(leaf_q$2$clock)
    );
    top$pipeline$leaf_q$3 leaf_q$3(
        .d(leaf_q$3$d),
        .q(leaf_q$3$q),
        .clock(leaf_q$3$clock)
    );
    top$pipeline$leaf_valid_q$0 leaf_valid_q$0(
        .d(leaf_valid_q$0$d),
        .q(leaf_valid_q$0$q),
        .clock(leaf_valid_q$0$clock)
    );
    top$pipeline$leaf_valid_q$1 leaf_valid_q$1(
        .d(leaf_valid_q$1$d),
        .q(leaf_valid_q$1$q),
        .clock(leaf_valid_q$1$clock)
    );
    top$pipeline$leaf_valid_q$2 leaf_valid_q$2(
        .d(leaf_valid_q$2$d),
        .q(leaf_valid_q$2$q),
        .clock(leaf_valid_q$2$clock)
    );
    top$pipeline$leaf_valid_q$3 leaf_valid_q$3(
        .d(leaf_valid_q$3$d),
        .q(leaf_valid_q$3$q),
        .clock(leaf_valid_q$3$clock)
    );
    top$pipeline$rpc rpc(
        .clock(rpc$clock),
        .leaf_r$0(rpc$leaf_r$0),
        .leaf_r$1(rpc$leaf_r$1),
        .leaf_r$2(rpc$leaf_r$2),
        .leaf_r$3(rpc$leaf_r$3),
        .leaf_g$0(rpc$leaf_g$0),
        .leaf_g$1(rpc$leaf_g$1),
        .leaf_g$2(rpc$leaf_g$2),
        .leaf_g$3(rpc$leaf_g$3),
        .leaf_b$0(rpc$leaf_b$0),
        .leaf_b$1(rpc$leaf_b$1),
        .leaf_b$2(rpc$leaf_b$2),
        .leaf_b$3(rpc$leaf_b$3),
        .leaf_a$0(rpc$leaf_a$0),
        .leaf_a$1(rpc$leaf_a$1),
        .leaf_a$2(rpc$leaf_a$2),
        .leaf_a$3(rpc$leaf_a$3),
        .leaf_valid$0(rpc$leaf_valid$0),
        .leaf_valid$1(rpc$leaf_valid$1),
        .leaf_valid$2(rpc$leaf_valid$2),
        .leaf_valid$3(rpc$leaf_valid$3),
        .first(rpc$first),
        .last(rpc$last),
        .done(rpc$done),
        .pixel_r(rpc$pixel_r),
        .pixel_g(rpc$pixel_g),
        .pixel_b(rpc$pixel_b),
        .pixel_a(rpc$pixel_a),
        .has_sample(rpc$has_sample)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lanes$clock = clock;
        rpc$clock = clock;
        control$start = start;
        control$valid = valid;
        lanes$first = control$first;
        flags_q$0$clock = clock;
        flags_q$1$clock = clock;
        flags_q$2$clock = clock;
        flags_q$3$clock = clock;
        flags_q$4$clock = clock;
        flags_q$5$clock = clock;
        flags_q$6$clock = clock;
        flags_q$7$clock = clock;
        flags_q$0$d = 16'(control$in_volume) | (16'(control$unit_valid) << 'h8) | (16'(control$unit_first) << 'h9) | (16'(control$unit_last) << 'ha);
        flags_q$1$d = flags_q$0$q;
        flags_q$2$d = flags_q$1$q;
        flags_q$3$d = flags_q$2$q;
        flags_q$4$d = flags_q$3$q;
        flags_q$5$d = flags_q$4$q;
        flags_q$6$d = flags_q$5$q;
        flags_q$7$d = flags_q$6$q;
        lanes$cur$0 = cur$0;
        lanes$next$0 = next$0;
        lanes$wx$0 = control$wx$0;
        lanes$wy$0 = control$wy$0;
        leaf_q$0$clock = clock;
        leaf_valid_q$0$clock = clock;
        row$0 = (lanes$sample$0 >> frac) >> row_shift;
        opacity$0$address = row$0[('h0)+:(12)];
        leaf_valid_q$0$d = |(flags_q$6$q & lane_bit$0);
        leaf_q$0$d = 'h0;
        if (|(flags_q$6$q & lane_bit$0)) begin
            leaf_q$0$d = (lanes$sample$0 + half) >> frac;
            if (xray) begin
                leaf_q$0$d = opacity$0$data;
            end
        end
        rpc$leaf_r$0 = leaf_q$0$q;
        rpc$leaf_g$0 = 'h0;
        rpc$leaf_b$0 = 'h0;
        rpc$leaf_a$0 = 'h0;
        rpc$leaf_valid$0 = leaf_valid_q$0$q;
        lanes$cur$1 = cur$1;
        lanes$next$1 = next$1;
        lanes$wx$1 = control$wx$1;
        lanes$wy$1 = control$wy$1;
        leaf_q$1$clock = clock;
        leaf_valid_q$1$clock = clock;
        row$1 = (lanes$sample$1 >> frac) >> row_shift;
        opacity$1$address = row$1[('h0)+:(12)];
        leaf_valid_q$1$d = |(flags_q$6$q & lane_bit$1);
        leaf_q$1$d = 'h0;
        if (|(flags_q$6$q & lane_bit$1)) begin
            leaf_q$1$d = (lanes$sample$1 + half) >> frac;
            if (xray) begin
                leaf_q$1$d = opacity$1$data;
            end
        end
        rpc$leaf_r$1 = leaf_q$1$q;
        rpc$leaf_g$1 = 'h0;
        rpc$leaf_b$1 = 'h0;
        rpc$leaf_a$1 = 'h0;
        rpc$leaf_valid$1 = leaf_valid_q$1$q;
        lanes$cur$2 = cur$2;
        lanes$next$2 = next$2;
        lanes$wx$2 = control$wx$2;
        lanes$wy$2 = control$wy$2;
        leaf_q$2$clock = clock;
        leaf_valid_q$2$clock = clock;
        row$2 = (lanes$sample$2 >> frac) >> row_shift;
        opacity$2$address = row$2[('h0)+:(12)];
        leaf_valid_q$2$d = |(flags_q$6$q & lane_bit$2);
        leaf_q$2$d = 'h0;
        if (|(flags_q$6$q & lane_bit$2)) begin
            leaf_q$2$d = (lanes$sample$2 + half) >> frac;
            if (xray) begin
                leaf_q$2$d = opacity$2$data;
            end
        end
        rpc$leaf_r$2 = leaf_q$2$q;
        rpc$leaf_g$2 = 'h0;
        rpc$leaf_b$2 = 'h0;
        rpc$leaf_a$2 = 'h0;
        rpc$leaf_valid$2 = leaf_valid_q$2$q;
        lanes$cur$3 = cur$3;
        lanes$next$3 = next$3;
        lanes$wx$3 = control$wx$3;
        lanes$wy$3 = control$wy$3;
        leaf_q$3$clock = clock;
        leaf_valid_q$3$clock = clock;
        row$3 = (lanes$sample$3 >> frac) >> row_shift;
        opacity$3$address = row$3[('h0)+:(12)];
        leaf_valid_q$3$d = |(flags_q$6$q & lane_bit$3);
        leaf_q$3$d = 'h0;
        if (|(flags_q$6$q & lane_bit$3)) begin
            leaf_q$3$d = (lanes$sample$3 + half) >> frac;
            if (xray) begin
                leaf_q$3$d = opacity$3$data;
            end
        end
        rpc$leaf_r$3 = leaf_q$3$q;
        rpc$leaf_g$3 = 'h0;
        rpc$leaf_b$3 = 'h0;
        rpc$leaf_a$3 = 'h0;
        rpc$leaf_valid$3 = leaf_valid_q$3$q;
        rpc$first = flags_q$7$q['h9] & flags_q$7$q['h8];
        rpc$last = flags_q$7$q['ha] & flags_q$7$q['h8];
        done = rpc$done;
        pixel_r = rpc$pixel_r;
        pixel_g = rpc$pixel_g;
        pixel_b = rpc$pixel_b;
        pixel_a = rpc$pixel_a;
        has_sample = rpc$has_sample;
    end
    
endmodule // top$pipeline
module top$pipeline$flags_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$0
module top$pipeline$flags_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$1
module top$pipeline$flags_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$2
module top$pipeline$flags_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$3
module top$pipeline$flags_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$4
module top$pipeline$flags_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$5
module top$pipeline$flags_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$6
module top$pipeline$flags_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$flags_q$7
module top$pipeline$leaf_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$0
module top$pipeline$leaf_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$1
module top$pipeline$leaf_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$2
module top$pipeline$leaf_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_q$3
module top$pipeline$leaf_valid_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$0
module top$pipeline$leaf_valid_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$1
module top$pipeline$leaf_valid_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$2
module top$pipeline$leaf_valid_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$leaf_valid_q$3
module top$pipeline$opacity$0(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$0
module top$pipeline$opacity$1(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$1
module top$pipeline$opacity$2(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$2
module top$pipeline$opacity$3(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 'h0;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$opacity$3
