module top$lanes$0$taps(clock,now,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    
    // Stub signals
    reg  t0$clock;
    reg  [15:0] t0$now;
    reg  [63:0] t0$res;
    reg  t0$res_beat;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [15:0] t1$now;
    reg  [63:0] t1$res;
    reg  t1$res_beat;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [15:0] t2$now;
    reg  [63:0] t2$res;
    reg  t2$res_beat;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [15:0] t3$now;
    reg  [63:0] t3$res;
    reg  t3$res_beat;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [15:0] t4$now;
    reg  [63:0] t4$res;
    reg  t4$res_beat;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [15:0] t5$now;
    reg  [63:0] t5$res;
    reg  t5$res_beat;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [15:0] t6$now;
    reg  [63:0] t6$res;
    reg  t6$res_beat;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [15:0] t7$now;
    reg  [63:0] t7$res;
    reg  t7$res_beat;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [15:0] t8$now;
    reg  [63:0] t8$res;
    reg  t8$res_beat;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$0$taps$t0 t0(
        .clock(t0$clock),
        .now(t0$now),
        .res(t0$res),
        .res_beat(t0$res_beat),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$0$taps$t1 t1(
        .clock(t1$clock),
        .now(t1$now),
        .res(t1$res),
        .res_beat(t1$res_beat),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$0$taps$t2 t2(
        .clock(t2$clock),
        .now(t2$now),
        .res(t2$res),
        .res_beat(t2$res_beat),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$0$taps$t3 t3(
        .clock(t3$clock),
        .now(t3$now),
        .res(t3$res),
        .res_beat(t3$res_beat),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$0$taps$t4 t4(
        .clock(t4$clock),
        .now(t4$now),
        .res(t4$res),
        .res_beat(t4$res_beat),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$0$taps$t5 t5(
        .clock(t5$clock),
        .now(t5$now),
        .res(t5$res),
        .res_beat(t5$res_beat),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$0$taps$t6 t6(
        .clock(t6$clock),
        .now(t6$now),
        .res(t6$res),
        .res_beat(t6$res_beat),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$0$taps$t7 t7(
        .clock(t7$clock),
        .now(t7$now),
        .res(t7$res),
        .res_beat(t7$res_beat),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$0$taps$t8 t8(
        .clock(t8$clock),
        .now(t8$now),
        .res(t8$res),
        .res_beat(t8$res_beat),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$now = now;
        t0$res = res;
        t0$res_beat = res_beat;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$now = now;
        t1$res = res;
        t1$res_beat = res_beat;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$now = now;
        t2$res = res;
        t2$res_beat = res_beat;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$now = now;
        t3$res = res;
        t3$res_beat = res_beat;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$now = now;
        t4$res = res;
        t4$res_beat = res_beat;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$now = now;
        t5$res = res;
        t5$res_beat = res_beat;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$now = now;
        t6$res = res;
        t6$res_beat = res_beat;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$now = now;
        t7$res = res;
        t7$res_beat = res_beat;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$now = now;
        t8$res = res;
        t8$res_beat = res_beat;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$0$taps
module top$lanes$0$taps$t0(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t0$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t0
module top$lanes$0$taps$t0$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t0$links$0
module top$lanes$0$taps$t0$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t0$prev
module top$lanes$0$taps$t0$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t0$ring
module top$lanes$0$taps$t1(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc03;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t1$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t1
module top$lanes$0$taps$t1$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t1$links$0
module top$lanes$0$taps$t1$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t1$links$1
module top$lanes$0$taps$t1$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t1$prev
module top$lanes$0$taps$t1$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t1$ring
module top$lanes$0$taps$t2(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t2$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t2
module top$lanes$0$taps$t2$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t2$prev
module top$lanes$0$taps$t2$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t2$ring
module top$lanes$0$taps$t3(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t3$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t3
module top$lanes$0$taps$t3$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t3$links$0
module top$lanes$0$taps$t3$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t3$links$1
module top$lanes$0$taps$t3$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t3$prev
module top$lanes$0$taps$t3$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t3$ring
module top$lanes$0$taps$t4(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc11;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t4$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t4
module top$lanes$0$taps$t4$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t4$prev
module top$lanes$0$taps$t4$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t4$ring
module top$lanes$0$taps$t5(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf4;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t5$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$0$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t5
module top$lanes$0$taps$t5$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t5$links$0
module top$lanes$0$taps$t5$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t5$links$1
module top$lanes$0$taps$t5$links$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t5$links$2
module top$lanes$0$taps$t5$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t5$prev
module top$lanes$0$taps$t5$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t5$ring
module top$lanes$0$taps$t6(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t6$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t6
module top$lanes$0$taps$t6$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t6$links$0
module top$lanes$0$taps$t6$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t6$prev
module top$lanes$0$taps$t6$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t6$ring
module top$lanes$0$taps$t7(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc12;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t7$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t7
module top$lanes$0$taps$t7$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t7$links$0
module top$lanes$0$taps$t7$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t7$prev
module top$lanes$0$taps$t7$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t7$ring
module top$lanes$0$taps$t8(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc13;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t8$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$0$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$0$taps$t8
module top$lanes$0$taps$t8$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t8$links$0
module top$lanes$0$taps$t8$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$t8$prev
module top$lanes$0$taps$t8$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$taps$t8$ring
module top$lanes$1$taps(clock,now,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    
    // Stub signals
    reg  t0$clock;
    reg  [15:0] t0$now;
    reg  [63:0] t0$res;
    reg  t0$res_beat;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [15:0] t1$now;
    reg  [63:0] t1$res;
    reg  t1$res_beat;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [15:0] t2$now;
    reg  [63:0] t2$res;
    reg  t2$res_beat;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [15:0] t3$now;
    reg  [63:0] t3$res;
    reg  t3$res_beat;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [15:0] t4$now;
    reg  [63:0] t4$res;
    reg  t4$res_beat;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [15:0] t5$now;
    reg  [63:0] t5$res;
    reg  t5$res_beat;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [15:0] t6$now;
    reg  [63:0] t6$res;
    reg  t6$res_beat;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [15:0] t7$now;
    reg  [63:0] t7$res;
    reg  t7$res_beat;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [15:0] t8$now;
    reg  [63:0] t8$res;
    reg  t8$res_beat;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$1$taps$t0 t0(
        .clock(t0$clock),
        .now(t0$now),
        .res(t0$res),
        .res_beat(t0$res_beat),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$1$taps$t1 t1(
        .clock(t1$clock),
        .now(t1$now),
        .res(t1$res),
        .res_beat(t1$res_beat),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$1$taps$t2 t2(
        .clock(t2$clock),
        .now(t2$now),
        .res(t2$res),
        .res_beat(t2$res_beat),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$1$taps$t3 t3(
        .clock(t3$clock),
        .now(t3$now),
        .res(t3$res),
        .res_beat(t3$res_beat),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$1$taps$t4 t4(
        .clock(t4$clock),
        .now(t4$now),
        .res(t4$res),
        .res_beat(t4$res_beat),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$1$taps$t5 t5(
        .clock(t5$clock),
        .now(t5$now),
        .res(t5$res),
        .res_beat(t5$res_beat),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$1$taps$t6 t6(
        .clock(t6$clock),
        .now(t6$now),
        .res(t6$res),
        .res_beat(t6$res_beat),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$1$taps$t7 t7(
        .clock(t7$clock),
        .now(t7$now),
        .res(t7$res),
        .res_beat(t7$res_beat),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$1$taps$t8 t8(
        .clock(t8$clock),
        .now(t8$now),
        .res(t8$res),
        .res_beat(t8$res_beat),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$now = now;
        t0$res = res;
        t0$res_beat = res_beat;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$now = now;
        t1$res = res;
        t1$res_beat = res_beat;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$now = now;
        t2$res = res;
        t2$res_beat = res_beat;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$now = now;
        t3$res = res;
        t3$res_beat = res_beat;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$now = now;
        t4$res = res;
        t4$res_beat = res_beat;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$now = now;
        t5$res = res;
        t5$res_beat = res_beat;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$now = now;
        t6$res = res;
        t6$res_beat = res_beat;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$now = now;
        t7$res = res;
        t7$res_beat = res_beat;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$now = now;
        t8$res = res;
        t8$res_beat = res_beat;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$1$taps
module top$lanes$1$taps$t0(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t0$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t0
module top$lanes$1$taps$t0$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t0$links$0
module top$lanes$1$taps$t0$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t0$prev
module top$lanes$1$taps$t0$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t0$ring
module top$lanes$1$taps$t1(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc03;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t1$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t1
module top$lanes$1$taps$t1$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t1$links$0
module top$lanes$1$taps$t1$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t1$links$1
module top$lanes$1$taps$t1$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t1$prev
module top$lanes$1$taps$t1$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t1$ring
module top$lanes$1$taps$t2(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t2$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t2
module top$lanes$1$taps$t2$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t2$prev
module top$lanes$1$taps$t2$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t2$ring
module top$lanes$1$taps$t3(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t3$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t3
module top$lanes$1$taps$t3$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t3$links$0
module top$lanes$1$taps$t3$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t3$links$1
module top$lanes$1$taps$t3$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t3$prev
module top$lanes$1$taps$t3$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t3$ring
module top$lanes$1$taps$t4(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc11;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t4$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t4
module top$lanes$1$taps$t4$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t4$prev
module top$lanes$1$taps$t4$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t4$ring
module top$lanes$1$taps$t5(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf4;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t5$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$1$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t5
module top$lanes$1$taps$t5$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t5$links$0
module top$lanes$1$taps$t5$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t5$links$1
module top$lanes$1$taps$t5$links$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t5$links$2
module top$lanes$1$taps$t5$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t5$prev
module top$lanes$1$taps$t5$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t5$ring
module top$lanes$1$taps$t6(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t6$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t6
module top$lanes$1$taps$t6$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t6$links$0
module top$lanes$1$taps$t6$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t6$prev
module top$lanes$1$taps$t6$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t6$ring
module top$lanes$1$taps$t7(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc12;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t7$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t7
module top$lanes$1$taps$t7$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t7$links$0
module top$lanes$1$taps$t7$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t7$prev
module top$lanes$1$taps$t7$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t7$ring
module top$lanes$1$taps$t8(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc13;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t8$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$1$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$1$taps$t8
module top$lanes$1$taps$t8$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t8$links$0
module top$lanes$1$taps$t8$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$t8$prev
module top$lanes$1$taps$t8$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$taps$t8$ring
module top$lanes$2$taps(clock,now,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    
    // Stub signals
    reg  t0$clock;
    reg  [15:0] t0$now;
    reg  [63:0] t0$res;
    reg  t0$res_beat;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [15:0] t1$now;
    reg  [63:0] t1$res;
    reg  t1$res_beat;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [15:0] t2$now;
    reg  [63:0] t2$res;
    reg  t2$res_beat;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [15:0] t3$now;
    reg  [63:0] t3$res;
    reg  t3$res_beat;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [15:0] t4$now;
    reg  [63:0] t4$res;
    reg  t4$res_beat;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [15:0] t5$now;
    reg  [63:0] t5$res;
    reg  t5$res_beat;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [15:0] t6$now;
    reg  [63:0] t6$res;
    reg  t6$res_beat;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [15:0] t7$now;
    reg  [63:0] t7$res;
    reg  t7$res_beat;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [15:0] t8$now;
    reg  [63:0] t8$res;
    reg  t8$res_beat;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$2$taps$t0 t0(
        .clock(t0$clock),
        .now(t0$now),
        .res(t0$res),
        .res_beat(t0$res_beat),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$2$taps$t1 t1(
        .clock(t1$clock),
        .now(t1$now),
        .res(t1$res),
        .res_beat(t1$res_beat),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$2$taps$t2 t2(
        .clock(t2$clock),
        .now(t2$now),
        .res(t2$res),
        .res_beat(t2$res_beat),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$2$taps$t3 t3(
        .clock(t3$clock),
        .now(t3$now),
        .res(t3$res),
        .res_beat(t3$res_beat),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$2$taps$t4 t4(
        .clock(t4$clock),
        .now(t4$now),
        .res(t4$res),
        .res_beat(t4$res_beat),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$2$taps$t5 t5(
        .clock(t5$clock),
        .now(t5$now),
        .res(t5$res),
        .res_beat(t5$res_beat),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$2$taps$t6 t6(
        .clock(t6$clock),
        .now(t6$now),
        .res(t6$res),
        .res_beat(t6$res_beat),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$2$taps$t7 t7(
        .clock(t7$clock),
        .now(t7$now),
        .res(t7$res),
        .res_beat(t7$res_beat),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$2$taps$t8 t8(
        .clock(t8$clock),
        .now(t8$now),
        .res(t8$res),
        .res_beat(t8$res_beat),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$now = now;
        t0$res = res;
        t0$res_beat = res_beat;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$now = now;
        t1$res = res;
        t1$res_beat = res_beat;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$now = now;
        t2$res = res;
        t2$res_beat = res_beat;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$now = now;
        t3$res = res;
        t3$res_beat = res_beat;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$now = now;
        t4$res = res;
        t4$res_beat = res_beat;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$now = now;
        t5$res = res;
        t5$res_beat = res_beat;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$now = now;
        t6$res = res;
        t6$res_beat = res_beat;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$now = now;
        t7$res = res;
        t7$res_beat = res_beat;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$now = now;
        t8$res = res;
        t8$res_beat = res_beat;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$2$taps
module top$lanes$2$taps$t0(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t0$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t0
module top$lanes$2$taps$t0$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t0$links$0
module top$lanes$2$taps$t0$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t0$prev
module top$lanes$2$taps$t0$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t0$ring
module top$lanes$2$taps$t1(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc03;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t1$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$2$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t1
module top$lanes$2$taps$t1$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t1$links$0
module top$lanes$2$taps$t1$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t1$links$1
module top$lanes$2$taps$t1$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t1$prev
module top$lanes$2$taps$t1$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t1$ring
module top$lanes$2$taps$t2(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t2$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t2
module top$lanes$2$taps$t2$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t2$prev
module top$lanes$2$taps$t2$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t2$ring
module top$lanes$2$taps$t3(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t3$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$2$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t3
module top$lanes$2$taps$t3$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t3$links$0
module top$lanes$2$taps$t3$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t3$links$1
module top$lanes$2$taps$t3$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t3$prev
module top$lanes$2$taps$t3$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t3$ring
module top$lanes$2$taps$t4(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc11;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t4$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t4
module top$lanes$2$taps$t4$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t4$prev
module top$lanes$2$taps$t4$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t4$ring
module top$lanes$2$taps$t5(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf4;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t5$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$2$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$2$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t5
module top$lanes$2$taps$t5$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t5$links$0
module top$lanes$2$taps$t5$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t5$links$1
module top$lanes$2$taps$t5$links$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t5$links$2
module top$lanes$2$taps$t5$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t5$prev
module top$lanes$2$taps$t5$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t5$ring
module top$lanes$2$taps$t6(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t6$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t6
module top$lanes$2$taps$t6$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t6$links$0
module top$lanes$2$taps$t6$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t6$prev
module top$lanes$2$taps$t6$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t6$ring
module top$lanes$2$taps$t7(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc12;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t7$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t7
module top$lanes$2$taps$t7$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t7$links$0
module top$lanes$2$taps$t7$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t7$prev
module top$lanes$2$taps$t7$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t7$ring
module top$lanes$2$taps$t8(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc13;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$2$taps$t8$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$2$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$2$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$2$taps$t8
module top$lanes$2$taps$t8$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t8$links$0
module top$lanes$2$taps$t8$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$taps$t8$prev
module top$lanes$2$taps$t8$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$taps$t8$ring
module top$lanes$3$taps(clock,now,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    
    // Stub signals
    reg  t0$clock;
    reg  [15:0] t0$now;
    reg  [63:0] t0$res;
    reg  t0$res_beat;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [15:0] t1$now;
    reg  [63:0] t1$res;
    reg  t1$res_beat;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [15:0] t2$now;
    reg  [63:0] t2$res;
    reg  t2$res_beat;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [15:0] t3$now;
    reg  [63:0] t3$res;
    reg  t3$res_beat;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [15:0] t4$now;
    reg  [63:0] t4$res;
    reg  t4$res_beat;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [15:0] t5$now;
    reg  [63:0] t5$res;
    reg  t5$res_beat;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [15:0] t6$now;
    reg  [63:0] t6$res;
    reg  t6$res_beat;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [15:0] t7$now;
    reg  [63:0] t7$res;
    reg  t7$res_beat;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [15:0] t8$now;
    reg  [63:0] t8$res;
    reg  t8$res_beat;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$3$taps$t0 t0(
        .clock(t0$clock),
        .now(t0$now),
        .res(t0$res),
        .res_beat(t0$res_beat),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$3$taps$t1 t1(
        .clock(t1$clock),
        .now(t1$now),
        .res(t1$res),
        .res_beat(t1$res_beat),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$3$taps$t2 t2(
        .clock(t2$clock),
        .now(t2$now),
        .res(t2$res),
        .res_beat(t2$res_beat),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$3$taps$t3 t3(
        .clock(t3$clock),
        .now(t3$now),
        .res(t3$res),
        .res_beat(t3$res_beat),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$3$taps$t4 t4(
        .clock(t4$clock),
        .now(t4$now),
        .res(t4$res),
        .res_beat(t4$res_beat),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$3$taps$t5 t5(
        .clock(t5$clock),
        .now(t5$now),
        .res(t5$res),
        .res_beat(t5$res_beat),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$3$taps$t6 t6(
        .clock(t6$clock),
        .now(t6$now),
        .res(t6$res),
        .res_beat(t6$res_beat),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$3$taps$t7 t7(
        .clock(t7$clock),
        .now(t7$now),
        .res(t7$res),
        .res_beat(t7$res_beat),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$3$taps$t8 t8(
        .clock(t8$clock),
        .now(t8$now),
        .res(t8$res),
        .res_beat(t8$res_beat),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$now = now;
        t0$res = res;
        t0$res_beat = res_beat;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$now = now;
        t1$res = res;
        t1$res_beat = res_beat;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$now = now;
        t2$res = res;
        t2$res_beat = res_beat;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$now = now;
        t3$res = res;
        t3$res_beat = res_beat;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$now = now;
        t4$res = res;
        t4$res_beat = res_beat;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$now = now;
        t5$res = res;
        t5$res_beat = res_beat;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$now = now;
        t6$res = res;
        t6$res_beat = res_beat;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$now = now;
        t7$res = res;
        t7$res_beat = res_beat;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$now = now;
        t8$res = res;
        t8$res_beat = res_beat;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$3$taps
module top$lanes$3$taps$t0(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t0$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t0
module top$lanes$3$taps$t0$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t0$links$0
module top$lanes$3$taps$t0$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t0$prev
module top$lanes$3$taps$t0$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t0$ring
module top$lanes$3$taps$t1(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc03;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t1$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$3$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t1
module top$lanes$3$taps$t1$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t1$links$0
module top$lanes$3$taps$t1$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t1$links$1
module top$lanes$3$taps$t1$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t1$prev
module top$lanes$3$taps$t1$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t1$ring
module top$lanes$3$taps$t2(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc02;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t2$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t2
module top$lanes$3$taps$t2$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t2$prev
module top$lanes$3$taps$t2$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t2$ring
module top$lanes$3$taps$t3(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t3$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$3$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t3
module top$lanes$3$taps$t3$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t3$links$0
module top$lanes$3$taps$t3$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t3$links$1
module top$lanes$3$taps$t3$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t3$prev
module top$lanes$3$taps$t3$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t3$ring
module top$lanes$3$taps$t4(clock,now,res,res_beat,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc11;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t4$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        stream = ring$read_data;
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t4
module top$lanes$3$taps$t4$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t4$prev
module top$lanes$3$taps$t4$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t4$ring
module top$lanes$3$taps$t5(clock,now,res,res_beat,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf4;
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t5$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$3$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$3$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = ring$read_data;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t5
module top$lanes$3$taps$t5$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t5$links$0
module top$lanes$3$taps$t5$links$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t5$links$1
module top$lanes$3$taps$t5$links$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t5$links$2
module top$lanes$3$taps$t5$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t5$prev
module top$lanes$3$taps$t5$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t5$ring
module top$lanes$3$taps$t6(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfbf3;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t6$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t6
module top$lanes$3$taps$t6$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t6$links$0
module top$lanes$3$taps$t6$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t6$prev
module top$lanes$3$taps$t6$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t6$ring
module top$lanes$3$taps$t7(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc12;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t7$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t7
module top$lanes$3$taps$t7$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t7$links$0
module top$lanes$3$taps$t7$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t7$prev
module top$lanes$3$taps$t7$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t7$ring
module top$lanes$3$taps$t8(clock,now,res,res_beat,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  [63:0] res;
    input wire  res_beat;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  offset = 16'hfc13;
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [15:0] ring$read_address;
    reg  ring$read_clock;
    wire  [63:0] ring$read_data;
    reg  [15:0] ring$write_address;
    reg  ring$write_clock;
    reg  [63:0] ring$write_data;
    reg  ring$write_enable;
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$3$taps$t8$ring ring(
        .read_address(ring$read_address),
        .read_clock(ring$read_clock),
        .read_data(ring$read_data),
        .write_address(ring$write_address),
        .write_clock(ring$write_clock),
        .write_data(ring$write_data),
        .write_enable(ring$write_enable)
    );
    top$lanes$3$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$3$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        ring$read_clock = clock;
        ring$write_clock = clock;
        ring$read_address = now + offset;
        ring$write_address = now - 'h3;
        ring$write_data = res;
        ring$write_enable = res_beat;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = ring$read_data;
        stream = ring$read_data;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a = prev$q;
        end
        else begin
            a = stream;
        end
    end
    
endmodule // top$lanes$3$taps$t8
module top$lanes$3$taps$t8$links$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t8$links$0
module top$lanes$3$taps$t8$prev(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$taps$t8$prev
module top$lanes$3$taps$t8$ring(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$taps$t8$ring
