module top$pipeline$lanes(clock,cur$0,cur$1,cur$2,cur$3,next$0,next$1,next$2,next$3,first,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3,sample$0,sample$1,sample$2,sample$3,offset,line_last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] cur$0;
    input wire  [15:0] cur$1;
    input wire  [15:0] cur$2;
    input wire  [15:0] cur$3;
    input wire  [15:0] next$0;
    input wire  [15:0] next$1;
    input wire  [15:0] next$2;
    input wire  [15:0] next$3;
    input wire  first;
    input wire  [15:0] wx$0;
    input wire  [15:0] wx$1;
    input wire  [15:0] wx$2;
    input wire  [15:0] wx$3;
    input wire  [15:0] wy$0;
    input wire  [15:0] wy$1;
    input wire  [15:0] wy$2;
    input wire  [15:0] wy$3;
    output reg  [31:0] sample$0;
    output reg  [31:0] sample$1;
    output reg  [31:0] sample$2;
    output reg  [31:0] sample$3;
    input wire  [15:0] offset;
    input wire  [15:0] line_last;
    
    // Stub signals
    reg  [15:0] cur_b$0$d;
    wire  [15:0] cur_b$0$q;
    reg  cur_b$0$clock;
    reg  [15:0] cur_b$1$d;
    wire  [15:0] cur_b$1$q;
    reg  cur_b$1$clock;
    reg  [15:0] cur_b$2$d;
    wire  [15:0] cur_b$2$q;
    reg  cur_b$2$clock;
    reg  [15:0] cur_b$3$d;
    wire  [15:0] cur_b$3$q;
    reg  cur_b$3$clock;
    reg  cur_line$0$clock;
    reg  [15:0] cur_line$0$data_in;
    reg  cur_line$0$write_enable;
    wire  [15:0] cur_line$0$data_out;
    reg  [15:0] cur_line$0$last;
    reg  cur_line$1$clock;
    reg  [15:0] cur_line$1$data_in;
    reg  cur_line$1$write_enable;
    wire  [15:0] cur_line$1$data_out;
    reg  [15:0] cur_line$1$last;
    reg  cur_line$2$clock;
    reg  [15:0] cur_line$2$data_in;
    reg  cur_line$2$write_enable;
    wire  [15:0] cur_line$2$data_out;
    reg  [15:0] cur_line$2$last;
    reg  cur_line$3$clock;
    reg  [15:0] cur_line$3$data_in;
    reg  cur_line$3$write_enable;
    wire  [15:0] cur_line$3$data_out;
    reg  [15:0] cur_line$3$last;
    reg  [15:0] cur_a$0$d;
    wire  [15:0] cur_a$0$q;
    reg  cur_a$0$clock;
    reg  [15:0] cur_a$1$d;
    wire  [15:0] cur_a$1$q;
    reg  cur_a$1$clock;
    reg  [15:0] cur_a$2$d;
    wire  [15:0] cur_a$2$q;
    reg  cur_a$2$clock;
    reg  [15:0] cur_a$3$d;
    wire  [15:0] cur_a$3$q;
    reg  cur_a$3$clock;
    reg  [15:0] next_b$0$d;
    wire  [15:0] next_b$0$q;
    reg  next_b$0$clock;
    reg  [15:0] next_b$1$d;
    wire  [15:0] next_b$1$q;
    reg  next_b$1$clock;
    reg  [15:0] next_b$2$d;
    wire  [15:0] next_b$2$q;
    reg  next_b$2$clock;
    reg  [15:0] next_b$3$d;
    wire  [15:0] next_b$3$q;
    reg  next_b$3$clock;
    reg  next_line$0$clock;
    reg  [15:0] next_line$0$data_in;
    reg  next_line$0$write_enable;
    wire  [15:0] next_line$0$data_out;
    reg  [15:0] next_line$0$last;
    reg  next_line$1$clock;
    reg  [15:0] next_line$1$data_in;
    reg  next_line$1$write_enable;
    wire  [15:0] next_line$1$data_out;
    reg  [15:0] next_line$1$last;
    reg  next_line$2$clock;
    reg  [15:0] next_line$2$data_in;
    reg  next_line$2$write_enable;
    wire  [15:0] next_line$2$data_out;
    reg  [15:0] next_line$2$last;
    reg  next_line$3$clock;
    reg  [15:0] next_line$3$data_in;
    reg  next_line$3$write_enable;
    wire  [15:0] next_line$3$data_out;
    reg  [15:0] next_line$3$last;
    reg  [15:0] next_a$0$d;
    wire  [15:0] next_a$0$q;
    reg  next_a$0$clock;
    reg  [15:0] next_a$1$d;
    wire  [15:0] next_a$1$q;
    reg  next_a$1$clock;
    reg  [15:0] next_a$2$d;
    wire  [15:0] next_a$2$q;
    reg  next_a$2$clock;
    reg  [15:0] next_a$3$d;
    wire  [15:0] next_a$3$q;
    reg  next_a$3$clock;
    reg  units$0$clock;
    reg  [15:0] units$0$a0;
    reg  [15:0] units$0$a1;
    reg  [15:0] units$0$b0;
    reg  [15:0] units$0$b1;
    reg  [15:0] units$0$c0;
    reg  [15:0] units$0$c1;
    reg  [15:0] units$0$d0;
    reg  [15:0] units$0$d1;
    reg  [15:0] units$0$offset;
    reg  [15:0] units$0$wx;
    reg  [15:0] units$0$wy;
    wire  [31:0] units$0$sample;
    reg  units$1$clock;
    reg  [15:0] units$1$a0;
    reg  [15:0] units$1$a1;
    reg  [15:0] units$1$b0;
    reg  [15:0] units$1$b1;
    reg  [15:0] units$1$c0;
    reg  [15:0] units$1$c1;
    reg  [15:0] units$1$d0;
    reg  [15:0] units$1$d1;
    reg  [15:0] units$1$offset;
    reg  [15:0] units$1$wx;
    reg  [15:0] units$1$wy;
    wire  [31:0] units$1$sample;
    reg  units$2$clock;
    reg  [15:0] units$2$a0;
    reg  [15:0] units$2$a1;
    reg  [15:0] units$2$b0;
    reg  [15:0] units$2$b1;
    reg  [15:0] units$2$c0;
    reg  [15:0] units$2$c1;
    reg  [15:0] units$2$d0;
    reg  [15:0] units$2$d1;
    reg  [15:0] units$2$offset;
    reg  [15:0] units$2$wx;
    reg  [15:0] units$2$wy;
    wire  [31:0] units$2$sample;
    reg  units$3$clock;
    reg  [15:0] units$3$a0;
    reg  [15:0] units$3$a1;
    reg  [15:0] units$3$b0;
    reg  [15:0] units$3$b1;
    reg  [15:0] units$3$c0;
    reg  [15:0] units$3$c1;
    reg  [15:0] units$3$d0;
    reg  [15:0] units$3$d1;
    reg  [15:0] units$3$offset;
    reg  [15:0] units$3$wx;
    reg  [15:0] units$3$wy;
    wire  [31:0] units$3$sample;
    
    // Local signals
    reg  [15:0] wrap_cur_b;
    reg  [15:0] wrap_cur_a;
    reg  [15:0] wrap_next_b;
    reg  [15:0] wrap_next_a;
    
    // Sub module instances
    top$pipeline$lanes$cur_b$0 cur_b$0(
        .d(cur_b$0$d),
        .q(cur_b$0$q),
        .clock(cur_b$0$clock)
    );
    top$pipeline$lanes$cur_b$1 cur_b$1(
        .d(cur_b$1$d),
        .q(cur_b$1$q),
        .clock(cur_b$1$clock)
    );
    top$pipeline$lanes$cur_b$2 cur_b$2(
        .d(cur_b$2$d),
        .q(cur_b$2$q),
        .clock(cur_b$2$clock)
    );
    top$pipeline$lanes$cur_b$3 cur_b$3(
        .d(cur_b$3$d),
        .q(cur_b$3$q),
        .clock(cur_b$3$clock)
    );
    top$pipeline$lanes$cur_line$0 cur_line$0(
        .clock(cur_line$0$clock),
        .data_in(cur_line$0$data_in),
        .write_enable(cur_line$0$write_enable),
        .data_out(cur_line$0$data_out),
        .last(cur_line$0$last)
    );
    top$pipeline$lanes$cur_line$1 cur_line$1(
        .clock(cur_line$1$clock),
        .data_in(cur_line$1$data_in),
        .write_enable(cur_line$1$write_enable),
        .data_out(cur_line$1$data_out),
        .last(cur_line$1$last)
    );
    top$pipeline$lanes$cur_line$2 cur_line$2(
        .clock(cur_line$2$clock),
        .data_in(cur_line$2$data_in),
        .write_enable(cur_line$2$write_enable),
        .data_out(cur_line$2$data_out),
        .last(cur_line$2$last)
    );
    top$pipeline$lanes$cur_line$3 cur_line$3(
        .clock(cur_line$3$clock),
        .data_in(cur_line$3$data_in),
        .write_enable(cur_line$3$write_enable),
        .data_out(cur_line$3$data_out),
        .last(cur_line$3$last)
    );
    top$pipeline$lanes$cur_a$0 cur_a$0(
        .d(cur_a$0$d),
        .q(cur_a$0$q),
        .clock(cur_a$0$clock)
    );
    top$pipeline$lanes$cur_a$1 cur_a$1(
        .d(cur_a$1$d),
        .q(cur_a$1$q),
        .clock(cur_a$1$clock)
    );
    top$pipeline$lanes$cur_a$2 cur_a$2(
        .d(cur_a$2$d),
        .q(cur_a$2$q),
        .clock(cur_a$2$clock)
    );
    top$pipeline$lanes$cur_a$3 cur_a$3(
        .d(cur_a$3$d),
        .q(cur_a$3$q),
        .clock(cur_a$3$clock)
    );
    top$pipeline$lanes$next_b$0 next_b$0(
        .d(next_b$0$d),
        .q(next_b$0$q),
        .clock(next_b$0$clock)
    );
    top$pipeline$lanes$next_b$1 next_b$1(
        .d(next_b$1$d),
        .q(next_b$1$q),
        .clock(next_b$1$clock)
    );
    top$pipeline$lanes$next_b$2 next_b$2(
        .d(next_b$2$d),
        .q(next_b$2$q),
        .clock(next_b$2$clock)
    );
    top$pipeline$lanes$next_b$3 next_b$3(
        .d(next_b$3$d),
        .q(next_b$3$q),
        .clock(next_b$3$clock)
    );
    top$pipeline$lanes$next_line$0 next_line$0(
        .clock(next_line$0$clock),
        .data_in(next_line$0$data_in),
        .write_enable(next_line$0$write_enable),
        .data_out(next_line$0$data_out),
        .last(next_line$0$last)
    );
    top$pipeline$lanes$next_line$1 next_line$1(
        .clock(next_line$1$clock),
        .data_in(next_line$1$data_in),
        .write_enable(next_line$1$write_enable),
        .data_out(next_line$1$data_out),
        .last(next_line$1$last)
    );
    top$pipeline$lanes$next_line$2 next_line$2(
        .clock(next_line$2$clock),
        .data_in(next_line$2$data_in),
        .write_enable(next_line$2$write_enable),
        .data_out(next_line$2$data_out),
        .last(next_line$2$last)
    );
    top$pipeline$lanes$next_line$3 next_line$3(
        .clock(next_line$3$clock),
        .data_in(next_line$3$data_in),
        .write_enable(next_line$3$write_enable),
        .data_out(next_line$3$data_out),
        .last(next_line$3$last)
    );
    top$pipeline$lanes$next_a$0 next_a$0(
        .d(next_a$0$d),
        .q(next_a$0$q),
        .clock(next_a$0$clock)
    );
    top$pipeline$lanes$next_a$1 next_a$1(
        .d(next_a$1$d),
        .q(next_a$1$q),
        .clock(next_a$1$clock)
    );
    top$pipeline$lanes$next_a$2 next_a$2(
        .d(next_a$2$d),
        .q(next_a$2$q),
        .clock(next_a$2$clock)
    );
    top$pipeline$lanes$next_a$3 next_a$3(
        .d(next_a$3$d),
        .q(next_a$3$q),
        .clock(next_a$3$clock)
    );
    top$pipeline$lanes$units$0 units$0(
        .clock(units$0$clock),
        .a0(units$0$a0),
        .a1(units$0$a1),
        .b0(units$0$b0),
        .b1(units$0$b1),
        .c0(units$0$c0),
        .c1(units$0$c1),
        .d0(units$0$d0),
        .d1(units$0$d1),
        .offset(units$0$offset),
        .wx(units$0$wx),
        .wy(units$0$wy),
        .sample(units$0$sample)
    );
    top$pipeline$lanes$units$1 units$1(
        .clock(units$1$clock),
        .a0(units$1$a0),
        .a1(units$1$a1),
        .b0(units$1$b0),
        .b1(units$1$b1),
        .c0(units$1$c0),
        .c1(units$1$c1),
        .d0(units$1$d0),
        .d1(units$1$d1),
        .offset(units$1$offset),
        .wx(units$1$wx),
        .wy(units$1$wy),
        .sample(units$1$sample)
    );
    top$pipeline$lanes$units$2 units$2(
        .clock(units$2$clock),
        .a0(units$2$a0),
        .a1(units$2$a1),
        .b0(units$2$b0),
        .b1(units$2$b1),
        .c0(units$2$c0),
        .c1(units$2$c1),
        .d0(units$2$d0),
        .d1(units$2$d1),
        .offset(units$2$offset),
        .wx(units$2$wx),
        .wy(units$2$wy),
        .sample(units$2$sample)
    );
    top$pipeline$lanes$units$3 units$3(
        .clock(units$3$clock),
        .a0(units$3$a0),
        .a1(units$3$a1),
        .b0(units$3$b0),
        .b1(units$3$b1),
        .c0(units$3$c0),
        .c1(units$3$c1),
        .d0(units$3$d0),
        .d1(units$3$d1),
        .offset(units$3$offset),
        .wx(units$3$wx),
        .wy(units$3$wy),
        .sample(units$3$sample)
    );
    
    // Update code
    always @(*) begin
        cur_b$0$clock = clock;
        cur_a$0$clock = clock;
        next_b$0$clock = clock;
        next_a$0$clock = clock;
        cur_line$0$clock = clock;
        next_line$0$clock = clock;
        units$0$clock = clock;
        cur_line$0$last = line_last;
        next_line$0$last = line_last;
        cur_line$0$write_enable = 1'b1;
        next_line$0$write_enable = 1'b1;
        cur_b$0$d = cur$0;
        cur_line$0$data_in = cur_b$0$q;
        cur_a$0$d = cur_line$0$data_out;
        next_b$0$d = next$0;
        next_line$0$data_in = next_b$0$q;
        next_a$0$d = next_line$0$data_out;
        units$0$a0 = cur_a$0$q;
        units$0$b0 = cur_b$0$q;
        units$0$c0 = next_a$0$q;
        units$0$d0 = next_b$0$q;
        units$0$offset = offset;
        units$0$wx = wx$0;
        units$0$wy = wy$0;
        sample$0 = units$0$sample;
        cur_b$1$clock = clock;
        cur_a$1$clock = clock;
        next_b$1$clock = clock;
        next_a$1$clock = clock;
        cur_line$1$clock = clock;
        next_line$1$clock = clock;
        units$1$clock = clock;
        cur_line$1$last = line_last;
        next_line$1$last = line_last;
        cur_line$1$write_enable = 1'b1;
        next_line$1$write_enable = 1'b1;
        cur_b$1$d = cur$1;
        cur_line$1$data_in = cur_b$1$q;
        cur_a$1$d = cur_line$1$data_out;
        next_b$1$d = next$1;
        next_line$1$data_in = next_b$1$q;
        next_a$1$d = next_line$1$data_out;
        units$1$a0 = cur_a$1$q;
        units$1$b0 = cur_b$1$q;
        units$1$c0 = next_a$1$q;
        units$1$d0 = next_b$1$q;
        units$1$offset = offset;
        units$1$wx = wx$1;
        units$1$wy = wy$1;
        sample$1 = units$1$sample;
        cur_b$2$clock = clock;
        cur_a$2$clock = clock;
        next_b$2$clock = clock;
        next_a$2$clock = clock;
        cur_line$2$clock = clock;
        next_line$2$clock = clock;
        units$2$clock = clock;
        cur_line$2$last = line_last;
        next_line$2$last = line_last;
        cur_line$2$write_enable = 1'b1;
        next_line$2$write_enable = 1'b1;
        cur_b$2$d = cur$2;
        cur_line$2$data_in = cur_b$2$q;
        cur_a$2$d = cur_line$2$data_out;
        next_b$2$d = next$2;
        next_line$2$data_in = next_b$2$q;
        next_a$2$d = next_line$2$data_out;
        units$2$a0 = cur_a$2$q;
        units$2$b0 = cur_b$2$q;
        units$2$c0 = next_a$2$q;
        units$2$d0 = next_b$2$q;
        units$2$offset = offset;
        units$2$wx = wx$2;
        units$2$wy = wy$2;
        sample$2 = units$2$sample;
        cur_b$3$clock = clock;
        cur_a$3$clock = clock;
        next_b$3$clock = clock;
        next_a$3$clock = clock;
        cur_line$3$clock = clock;
        next_line$3$clock = clock;
        units$3$clock = clock;
        cur_line$3$last = line_last;
        next_line$3$last = line_last;
        cur_line$3$write_enable = 1'b1;
        next_line$3$write_enable = 1'b1;
        cur_b$3$d = cur$3;
        cur_line$3$data_in = cur_b$3$q;
        cur_a$3$d = cur_line$3$data_out;
        next_b$3$d = next$3;
        next_line$3$data_in = next_b$3$q;
        next_a$3$d = next_line$3$data_out;
        units$3$a0 = cur_a$3$q;
        units$3$b0 = cur_b$3$q;
        units$3$c0 = next_a$3$q;
        units$3$d0 = next_b$3$q;
        units$3$offset = offset;
        units$3$wx = wx$3;
        units$3$wy = wy$3;
        sample$3 = units$3$sample;
        units$0$a1 = cur_a$1$q;
        units$0$b1 = cur_b$1$q;
        units$0$c1 = next_a$1$q;
        units$0$d1 = next_b$1$q;
        units$1$a1 = cur_a$2$q;
        units$1$b1 = cur_b$2$q;
        units$1$c1 = next_a$2$q;
        units$1$d1 = next_b$2$q;
        units$2$a1 = cur_a$3$q;
        units$2$b1 = cur_b$3$q;
        units$2$c1 = next_a$3$q;
        units$2$d1 = next_b$3$q;
        wrap_cur_a = cur_line$0$data_out;
        wrap_cur_b = cur$0;
        wrap_next_a = next_line$0$data_out;
        wrap_next_b = next$0;
        if (first) begin
            wrap_cur_a = 'h0;
            wrap_cur_b = 'h0;
            wrap_next_a = 'h0;
            wrap_next_b = 'h0;
        end
        units$3$a1 = wrap_cur_a;
        units$3$b1 = wrap_cur_b;
        units$3$c1 = wrap_next_a;
        units$3$d1 = wrap_next_b;
    end
    
endmodule // top$pipeline$lanes
module top$pipeline$lanes$cur_a$0(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_a$0
module top$pipeline$lanes$cur_a$1(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_a$1
module top$pipeline$lanes$cur_a$2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_a$2
module top$pipeline$lanes$cur_a$3(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_a$3
module top$pipeline$lanes$cur_b$0(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_b$0
module top$pipeline$lanes$cur_b$1(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_b$1
module top$pipeline$lanes$cur_b$2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_b$2
module top$pipeline$lanes$cur_b$3(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_b$3
module top$pipeline$lanes$cur_line$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$cur_line$0$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$cur_line$0$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$cur_line$0$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$cur_line$0$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$cur_line$0
module top$pipeline$lanes$cur_line$0$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$0$one
module top$pipeline$lanes$cur_line$0$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$0$ptr
module top$pipeline$lanes$cur_line$0$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$cur_line$0$ram
module top$pipeline$lanes$cur_line$0$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$0$rd_flipped
module top$pipeline$lanes$cur_line$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$cur_line$1$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$cur_line$1$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$cur_line$1$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$cur_line$1$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$cur_line$1
module top$pipeline$lanes$cur_line$1$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$1$one
module top$pipeline$lanes$cur_line$1$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$1$ptr
module top$pipeline$lanes$cur_line$1$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$cur_line$1$ram
module top$pipeline$lanes$cur_line$1$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$1$rd_flipped
module top$pipeline$lanes$cur_line$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$cur_line$2$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$cur_line$2$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$cur_line$2$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$cur_line$2$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$cur_line$2
module top$pipeline$lanes$cur_line$2$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$2$one
module top$pipeline$lanes$cur_line$2$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$2$ptr
module top$pipeline$lanes$cur_line$2$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$cur_line$2$ram
module top$pipeline$lanes$cur_line$2$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$2$rd_flipped
module top$pipeline$lanes$cur_line$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$cur_line$3$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$cur_line$3$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$cur_line$3$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$cur_line$3$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$cur_line$3
module top$pipeline$lanes$cur_line$3$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$3$one
module top$pipeline$lanes$cur_line$3$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$3$ptr
module top$pipeline$lanes$cur_line$3$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$cur_line$3$ram
module top$pipeline$lanes$cur_line$3$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$cur_line$3$rd_flipped
module top$pipeline$lanes$next_a$0(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_a$0
module top$pipeline$lanes$next_a$1(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_a$1
module top$pipeline$lanes$next_a$2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_a$2
module top$pipeline$lanes$next_a$3(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_a$3
module top$pipeline$lanes$next_b$0(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_b$0
module top$pipeline$lanes$next_b$1(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_b$1
module top$pipeline$lanes$next_b$2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_b$2
module top$pipeline$lanes$next_b$3(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_b$3
module top$pipeline$lanes$next_line$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$next_line$0$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$next_line$0$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$next_line$0$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$next_line$0$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$next_line$0
module top$pipeline$lanes$next_line$0$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$0$one
module top$pipeline$lanes$next_line$0$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$0$ptr
module top$pipeline$lanes$next_line$0$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$next_line$0$ram
module top$pipeline$lanes$next_line$0$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$0$rd_flipped
module top$pipeline$lanes$next_line$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$next_line$1$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$next_line$1$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$next_line$1$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$next_line$1$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$next_line$1
module top$pipeline$lanes$next_line$1$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$1$one
module top$pipeline$lanes$next_line$1$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$1$ptr
module top$pipeline$lanes$next_line$1$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$next_line$1$ram
module top$pipeline$lanes$next_line$1$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$1$rd_flipped
module top$pipeline$lanes$next_line$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$next_line$2$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$next_line$2$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$next_line$2$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$next_line$2$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$next_line$2
module top$pipeline$lanes$next_line$2$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$2$one
module top$pipeline$lanes$next_line$2$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$2$ptr
module top$pipeline$lanes$next_line$2$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$next_line$2$ram
module top$pipeline$lanes$next_line$2$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$2$rd_flipped
module top$pipeline$lanes$next_line$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h6;
    localparam  single = 1'b0;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$lanes$next_line$3$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$lanes$next_line$3$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$lanes$next_line$3$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$lanes$next_line$3$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$lanes$next_line$3
module top$pipeline$lanes$next_line$3$one(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$3$one
module top$pipeline$lanes$next_line$3$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$3$ptr
module top$pipeline$lanes$next_line$3$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[6:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$lanes$next_line$3$ram
module top$pipeline$lanes$next_line$3$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$next_line$3$rd_flipped
